#pragma once

// Parameter numbers the simulator acts on, as the M350 documents them (macro variable = N + 500).
// The full catalogue with names, units and ranges is data in resources/; these are the ones code
// reads by meaning.
namespace m350::param {

inline constexpr int kDefaultFeed = 61;            // 默认进给速度, mm/min
inline constexpr int kFeedAcceleration = 62;       // G01 acceleration, mm/s^2
inline constexpr int kRapidSpeed = 63;             // G00 speed, mm/min
inline constexpr int kMaxSpeed = 64;               // maximum speed, mm/min
inline constexpr int kSpindleStartDelay = 81;      // s, the program waits for the spindle to reach speed
inline constexpr int kMaxSpindleRpm = 82;
inline constexpr int kDefaultSpindleSpeed = 85;      // rpm for M3/M4 before any S, and the spindle jog key
inline constexpr int kOverrideActsOnRapids = 253; // 1: the feed override also scales G00
inline constexpr int kMaxFeedOverride = 295;      // %, the highest feed override the panel allows
inline constexpr int kFileSortOrder = 149;        // the program list: 0 by name, 1 by extension, 2 by date
inline constexpr int kSpindleStopDelay = 89;       // s, the spindle coasts to a stop
inline constexpr int kRapidAcceleration = 282;     // G00 acceleration, mm/s^2 (0: use 62)
inline constexpr int kSpindleStoppedInput = 620;   // input triple: pin, enable, active level (M300)
inline constexpr int kCoolantResponse = 92;        // 冷却指令(M8/M9)响应持续延时, s: how long M8 and M9 take
inline constexpr int kLubricationResponse = 94;    // 润滑指令(M10/M11)响应持续延时, s: how long M10 and M11 take
inline constexpr int kCoolantOutput = 730;         // output triple 冷却 (M8/M9)
inline constexpr int kLubricationOutput = 733;     // output triple 润滑 (M10/M11)
inline constexpr int kFixedSetterInput = 575;      // input triple of the fixed tool setter (固定对刀信号)
inline constexpr int kFixedSetterX = 135;          // 135-137: the fixed setter's machine X, Y and start Z
inline constexpr int kFixedSetterValid = 130;      // 固定对刀仪是否有效: tools are set on the fixed setter
inline constexpr int kSetterSafeZ = 141;           // 对刀前Z安全高度(机械坐标): O502 rises here first
inline constexpr int kFloatingSetterValid = 128;   // 浮动对刀仪是否有效
inline constexpr int kFloatingSetterInput = 578;   // input triple of the floating setter (浮动对刀信号)
inline constexpr int kUserKeyFunction = 210;       // 210-216: K1-K7: 0 key-N.nc, 1-21 an output, >1000 a panel key code
inline constexpr int kExternKeyFunction = 272;     // 272-277: external keys 1-6, the same choices (extnc<N-1>-1.nc)
inline constexpr int kExternStartInput = 599;      // input triple of the extern START key (外部启动)
inline constexpr int kCurrentWorkSystem = 78;      // #578: 0 = G92, 1..6 = G54..G59
inline constexpr int kPauseLift = 70;              // mm Z rises on pause when param 91 = 1
inline constexpr int kStopSpindleOnPause = 84;     // 1 = the spindle stops while paused
inline constexpr int kPauseZMode = 91;             // 0 = Z stays, 1 = Z rises by param 70
inline constexpr int kSafeZ = 69;                  // Z轴安全位置, work Z
inline constexpr int kLiftBeforeStart = 90;        // 0 = no action, 1 = Z to the safe height (param 69) first
inline constexpr int kPauseResumeMode = 93;        // 0 = from the block's start point, 1 = from the current point
inline constexpr int kHomePositionX = 122;         // 122-126: machine position after homing (G28 goes here)
inline constexpr int kHomingCycles = 106;          // approaches to the switch
inline constexpr int kHomingSpeedX = 107;          // 107-111, mm/min (deg/min)
inline constexpr int kHomingDirectionX = 112;      // 112-116: 0 negative, 1 positive
inline constexpr int kHomingSecondSpeed = 118;     // mm/min of the precise approaches (0: a tenth of the first)
inline constexpr int kHomeMode = 100;              // 机械零点方式: 0 home switches, 1 absolute servos
inline constexpr int kHomeAfterBooting = 127;      // 0 = prompt 是否进行开机寻零操作? at boot
inline constexpr int kHomeSwitchX = 545;           // input triples 545, 548, 551, 554, 557: pin, enable, level
inline constexpr int kModbusRtu = 279;              // Modbus RTU: 0 off, 1 on (MSETDATA / MGETDATA)
inline constexpr int kHomeBeforeProcessing = 220;  // 0 = not required
inline constexpr int kDrillingRetraction = 224;    // 钻孔循环退刀量, mm: G73/G83 retraction
inline constexpr int kSoftLimitsEnabled = 155;     // 0 = off
inline constexpr int kSoftLimitNegativeX = 161;    // 161-165 negative, 166-170 positive, machine coordinates
inline constexpr int kSoftLimitPositiveX = 166;
inline constexpr int kTotalRunCount = 201;         // #701 总加工数, counted by M30
inline constexpr int kPieceCount = 202;            // #702 加工件数, counted by M30
inline constexpr int kFourthAxisType = 449;       // 0 linear, 1 rotary; 450 the 5th axis
inline constexpr int kMotorAxisFirst = 488;        // 488-492: the programmed axis motor 1-5 drives (0 X .. 4 the 5th)
inline constexpr int kCurrentTool = 800;           // #1300 当前刀具号
inline constexpr int kMagazineCapacity = 801;      // #1301 刀库容量
inline constexpr int kMagazineType = 802;          // #1302 刀库类型
inline constexpr int kVirtualTools = 803;         // #1303 虚拟刀是否有效: tools above the capacity are changed by hand
inline constexpr int kToolReleasedInput = 623;     // input triple 刀具松开检测 (M301)
inline constexpr int kToolClampedInput = 626;      // input triple 刀具锁紧检测 (M302)
inline constexpr int kDrawbarOutput = 750;         // output triple 刀具松开/锁紧 (M154/M155)
inline constexpr int kMagazineSlideOutput = 753;   // output triple 刀库推出/收回 (M152/M153)
inline constexpr int kMultiProcessOutput1 = 777;   // output triples 777, 780, 783, 786: 多工序气缸1-4 (M168-M175)
inline constexpr int kChangeZUp = 806;             // #1306 换刀上位, machine Z
inline constexpr int kChangeZDown = 807;           // #1307 换刀下位: nose Z with a tool seated (servo disc station)
inline constexpr int kChangeFrontX = 808;          // #1308/#1309 换刀前置点 X/Y: the servo disc's station
inline constexpr int kChangeFrontY = 809;
inline constexpr int kSpindleLockDelay = 814;      // #1314 主轴锁紧输出延时, ms: how long the clamp cylinder takes
inline constexpr int kManualChangeX = 816;         // #1316-#1318 手动换刀 X/Y/Z, machine: where a tool is changed by hand
inline constexpr int kPocketX = 830;               // pocket k: X 830+k-1, Y 850+k-1, Z 870+k-1 (machine)
inline constexpr int kPocketY = 850;
inline constexpr int kPocketZ = 870;
inline constexpr int kToolXOffsetFirst = 890;      // #1390-#1399: T1..T10 X offset (a multi-process head's from the spindle)
inline constexpr int kToolYOffsetFirst = 910;      // #1410-#1425: T1..T16 Y offset
inline constexpr int kToolZOffsetFirst = 930;      // #1430-#1445: T1..T16 Z offset (machine Z at the setter)
inline constexpr int kToolZOffsetCount = 16;
inline constexpr int kVirtualToolZOffsetFirst = 973; // #1473-#1492: virtual tools 1..20
inline constexpr int kVirtualToolZOffsetCount = 20;

// Manual motion (手动参数, 手轮参数): per-axis parameters run X Y Z 4th 5th from the first number.
inline constexpr int kManualMaxSpeedX = 35;        // 35-39 手动最大速度, mm/min (deg/min): caps every jog
inline constexpr int kManualHighSpeedX = 40;       // 40-44 手动高速, mm/min
inline constexpr int kManualLowSpeedX = 45;        // 45-49 手动低速, mm/min
inline constexpr int kManualStartAccelerationX = 50; // 50-54 手动启动加速度, mm/s^2
inline constexpr int kManualStopAccelerationX = 55;  // 55-59 手动停止加速度, mm/s^2: a released key
inline constexpr int kMpgPrecise = 171;            // 手轮精准控制模式: 0 开启 (every pulse runs out), 1 关闭 (factory)
inline constexpr int kMpgDistance = 172;           // 手轮X1距离: mm per detent at x1
inline constexpr int kMpgReversed = 175;           // 手轮方向: 0 positive, 1 negative
inline constexpr int kMpgSpeedX1 = 176;            // 176, 177, 178: speed at x1, x10, x100, mm/min
inline constexpr int kGuideStopStep = 179;         // 试切: override step per interval once the wheel stops (0.05 = 5 %)
inline constexpr int kGuideChangeStep = 180;       // 试切: override step per interval as the wheel speeds up or slows down
inline constexpr int kMpgAccelerationX = 181;      // 181-185 手轮移动加速度, mm/s^2

} // namespace m350::param
