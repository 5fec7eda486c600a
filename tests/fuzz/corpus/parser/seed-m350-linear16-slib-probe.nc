// slib-probe.nc: tool setting (对刀) for every bundled M350 machine, written for M350 Studio after
// the M350 manual's chapter "换刀后对刀设置" and the firmware's flow. On a real controller these
// programs live in slib-g.nc; here one file serves all the M350 machine folders (machine.toml:
// [libraries] other). The Probe page's softkeys and the hook files run them:
//   O502  对刀: #1502 = 0 floating setter, 1 first fixed setting, 2 fixed setting (after a change)
//   O505  多刀固定对刀: every tool listed in #1970-#1989 changed to and set on the fixed setter
//   O506  XY位置教导: the machine X Y here become the fixed setter's position (params 135, 136)
//   O507  Z位置教导: the machine Z here becomes where probing starts (param 137)
//
// What the numbers mean (the manual's 对刀原理): work Z = machine Z - G54..G59 Z - the tool's Z
// offset, A = B - C - D. A tool's Z offset (params 930-945, virtual tools 973-992) is the machine
// Z at which it trips the fixed setter, so every set tool agrees on one work Z zero.
//
// #3000 = n(text) stops the run with alarm 3000+n. That is a simulator extra: the M350 firmware
// has no variable above #2999 and its own O502 only shows the text on the status line (#1503).
//   3001 no tool in the spindle        3002 X Y Z not homed           3003 no Z offset for the tool
//   3004 the setter is switched off    3005 its input is not wired    3006 the passes disagree
//   3007 #1502 is no mode              3008 a change of a multi-tool setting did not happen
// A setter that never trips stops the run in G31 itself (alarm skip_not_triggered).

O502(对刀 tool setting: #1502 = 0 floating, 1 first fixed, 2 fixed after a change)
#19 = 0.05                          //the most the passes may disagree, mm
IF [#1515+#1516+#1517] GE 3 GOTO1   //X Y Z homed: the setter and the offsets are machine positions
#3000 = 2(X,Y,Z轴机械未全部归零! home X, Y and Z before setting a tool)
N1 IF #1300 != 0 GOTO2
#3000 = 1(当前刀位空刀不能对刀!)
N2 #28 = 1430 + #1300 - 1           //the tool's Z offset: params 930-945 are #1430-#1445
IF #1300 LE #1301 GOTO3
#28 = 1473 + #1300 - #1301 - 1      //a virtual tool's: params 973-992 (param 803 on)
IF [#1303 != 0] * [#1300 - #1301 LE 20] GOTO3
#3000 = 3(刀具号超出范围! the tool is neither in the magazine nor a virtual tool: params 801, 803)
N3 IF #1502 == 0 GOTO20
IF [#1502 == 1] + [#1502 == 2] GOTO4
#3000 = 7(对刀方式错误! #1502 must be 0 floating, 1 first fixed or 2 fixed)

N4 IF #630 != 0 GOTO5               //fixed setter (固定对刀仪)
#3000 = 4(固定对刀仪无效! the fixed setter is switched off: param 130)
N5 IF [#1076 != 0] * [#1075 GE 1] GOTO6
#3000 = 5(固定对刀信号未设置! the fixed setter input, params 575-577, is not set)
N6 #25 = #1075                      //G31 on the fixed setter's input
#26 = #1077                         //at its active level
#10 = #635                          //over the setter: params 135, 136
#11 = #636
IF #1302 != 1 GOTO7                 //multi-process heads: each head's X Y from head 1's
#10 = #635 + #[1390 + #1300 - 1]
#11 = #636 + #[1410 + #1300 - 1]
N7 #1503 = 1(固定对刀: 移到对刀仪...)
G90 G53 Z#641                       //up to the safe height first (param 141)
G53 X#10 Y#11                       //over the setter
G53 Z#637                           //down to where probing starts (param 137)
GOTO30

N20 IF #628 != 0 GOTO21             //floating setter (浮动对刀仪): a block lying on the work
#3000 = 4(浮动对刀仪无效! the floating setter is switched off: param 128)
N21 IF [#1079 != 0] * [#1078 GE 1] GOTO22
#3000 = 5(浮动对刀信号未设置! the floating setter input, params 578-580, is not set)
N22 #25 = #1078                     //G31 on the floating setter's input, from where the tool stands
#26 = #1080

N30 #20 = #632                      //the first pass at param 132's speed, each later one at half
#21 = 0                             //the sum of the trip heights
#22 = 0                             //passes made
#23 = 99999                         //the lowest trip height
#24 = -99999                        //the highest
#27 = #882 - 200                    //search at most 200 mm down,
IF [#655 == 0] + [#27 GE #663] GOTO31
#27 = #663                          //and not beyond the Z soft limit (params 155, 163)
N31 IF #[1520+#25-1] != #26 GOTO32
G91 G31 Z10 F#20 P#25 L[1-#26] K0 Q1 //already on the setter: leave it upward first
G90
N32 WHILE [#22 LT #631] DO1         //param 131 passes
#1510 = #22 + 1
#1511 = #631
#1503 = 1(对刀信号搜索中 %.0f/%.0f...)
G91 G31 Z[#27-#882] F#20 P#25 L#26 K0 Q1 //down until the setter trips
#29 = #1927                         //the machine Z where it tripped
G31 Z10 F#20 P#25 L[1-#26] K0 Q1    //back up until it lets go
G01 Z1 F#20                         //and a run-up for the next, slower pass
G90
#21 = #21 + #29
IF #29 GE #23 GOTO33
#23 = #29
N33 IF #29 LE #24 GOTO34
#24 = #29
N34 #20 = #20 / 2
#22 = #22 + 1
END1
#1510 = #24 - #23
#1511 = #19
IF #1510 LE #19 GOTO35
#1503 = 1(对刀误差 %.3f mm, 允许 %.3f mm)
#3000 = 6(对刀误差过大! the passes disagree beyond the tolerance: see the message before this alarm)
N35 #23 = #21 / #631                //the average trip height
#24 = 807 + [#578 - 1] * 5          //the active work system's Z (#802 for G92)
IF #1502 == 0 GOTO37
IF #1502 == 2 GOTO36
#[#24] = #[#24] + #[#28] - #23      //mode 1: the work zero stays where it is, now relative to the setter
#1508 = 1                           //first setting done
N36 #[#28] = #23                    //the tool's Z offset: where it trips the setter
GOTO38
N37 #[#24] = #23 - #629 - #[#28]    //floating: work Z 0 lies the block's thickness (param 129) below
#1508 = 1
N38 #29 = #882 + #640                //back off by param 140,
IF #29 LE #641 GOTO39
#29 = #641                          //no higher than the safe height (param 141)
N39 G90 G53 Z#29
#1503 = 1(对刀完成!)
#1509 = 1                           //beep
G04 P200
#1509 = 0
M99

O505(多刀固定对刀 multi-tool setting: every tool listed in #1970-#1989 on the fixed setter)
// The Probe page lists the chosen tools in #1970-#1989 (0 = none, any order) and runs
// mulprobe.nc (M98 P505). Each listed tool is changed to (T, O20000) and set on the fixed setter
// (#1502 = 2, O502); #1993 is 1 while the batch changes a tool, so a change can tell it is part of
// one (the factory's O20000 leaves the dust cover closed then). An alarm stops the batch where it
// is: the tools set before it keep their new offsets.
#30 = 0                             //how many tools are listed
#31 = 0
WHILE [#31 LT 20] DO1
IF #[1970+#31] == 0 GOTO1
#30 = #30 + 1
N1 #31 = #31 + 1
END1
#32 = 0                             //tools set so far
#31 = 0
WHILE [#31 LT 20] DO2
#33 = #[1970+#31]
#31 = #31 + 1
IF #33 == 0 GOTO3                   //no tool in this place of the list
#32 = #32 + 1
#1510 = #33
#1511 = #32
#1512 = #30
#1503 = 1(多刀对刀 T%.0f: %.0f/%.0f...)
#34 = #1300                         //the tool before the change
#1993 = 1
T#33
#1993 = 0
IF #1300 == #33 GOTO2
#3000 = 8(多刀对刀停止: 换刀未完成! the change did not happen: see the message before this alarm)
N2 IF [#1305 != 0] * [#34 != #33] GOTO3 //param 805: the change has set the tool already
#1502 = 2
M98 P502
N3 END2
#1510 = #32
#1503 = 1(多刀对刀完成! %.0f把刀)
M99

O506(XY位置教导 XY teach: the machine X Y here become the fixed setter's position, params 135 136)
IF [#1515+#1516] GE 2 GOTO1
#3000 = 2(X,Y轴机械未归零! home X and Y before teaching the setter's position)
N1 #635 = #880
#636 = #881
#1510 = #880
#1511 = #881
#1503 = 1(固定对刀仪XY位置: X%.3f Y%.3f)
M99

O507(Z位置教导 Z teach: the machine Z here becomes where probing starts, param 137)
IF #1517 GE 1 GOTO1
#3000 = 2(Z轴机械未归零! home Z before teaching where probing starts)
N1 #637 = #882
#1510 = #882
#1503 = 1(固定对刀仪Z位置: Z%.3f)
M99
