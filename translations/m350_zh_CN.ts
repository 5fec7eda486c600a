<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="zh_CN">
<context>
    <name>m350::ui::ActionRecorder</name>
    <message>
        <source>%1: cannot write: %2</source>
        <translation>%1: 无法写入: %2</translation>
    </message>
    <message>
        <source>it is a folder</source>
        <translation>它是文件夹</translation>
    </message>
</context>
<context>
    <name>m350::ui::AttemptRun</name>
    <message>
        <source>no folder for the attempt's machine: %1</source>
        <translation>无法为本次练习建立机床文件夹：%1</translation>
    </message>
    <message>
        <source>Training: %1 · time left %2:%3 · F7: task, hint, hand in</source>
        <translation>训练：%1 · 剩余 %2:%3 · F7：任务、提示、交卷</translation>
    </message>
</context>
<context>
    <name>m350::ui::BackupImportFlow</name>
    <message>
        <source>Controller backup: the folder that holds setting, slib-g.nc ...</source>
        <translation>控制器备份: 包含 setting、slib-g.nc 等文件的文件夹</translation>
    </message>
    <message>
        <source>New machine folder (a new or empty folder)</source>
        <translation>新机床文件夹 (新建或空文件夹)</translation>
    </message>
    <message>
        <source>An import is under way: wait for its report</source>
        <translation>正在导入,请等待导入报告</translation>
    </message>
    <message>
        <source>Importing %1 ...</source>
        <translation>正在导入 %1 ...</translation>
    </message>
    <message>
        <source>Import refused:
%1: %2</source>
        <translation>导入被拒绝:
%1: %2</translation>
    </message>
    <message>
        <source>%1 already holds this backup's import; nothing written</source>
        <translation>%1 已是此备份的导入结果, 未写入任何文件</translation>
    </message>
    <message>
        <source>Machine folder made from the backup:
%1</source>
        <translation>已由备份生成机床文件夹:
%1</translation>
    </message>
    <message>
        <source>%1 parameters, %2 differ from the factory values</source>
        <translation>%1 个参数, 其中 %2 个与出厂值不同</translation>
    </message>
    <message>
        <source>.nc files copied as they were: %1; other files not copied: %2</source>
        <translation>%1 个 .nc 文件原样复制, %2 个文件未复制</translation>
    </message>
    <message>
        <source>%1 stated values to review in machine.toml</source>
        <translation>machine.toml 中有 %1 项设定值需要核对</translation>
    </message>
    <message>
        <source>The simulator cannot model:</source>
        <translation>模拟器无法模拟:</translation>
    </message>
    <message>
        <source>%1 syntax errors the simulator does not accept yet</source>
        <translation>%1 处语法错误: 模拟器尚不接受</translation>
    </message>
    <message>
        <source>The whole report: %1</source>
        <translation>完整报告: %1</translation>
    </message>
    <message>
        <source>Open it with: m350-hmi --config %1</source>
        <translation>打开方式: m350-hmi --config %1</translation>
    </message>
    <message>
        <source>Switch the panel to this machine now?</source>
        <translation>是否将面板切换到此机床?</translation>
    </message>
</context>
<context>
    <name>m350::ui::BreakRunPage</name>
    <message>
        <source>Break Run</source>
        <comment>msg 317</comment>
        <translation>断点加工</translation>
    </message>
    <message>
        <source>Start Line</source>
        <comment>msg 456</comment>
        <translation>指定行加工</translation>
    </message>
    <message>
        <source>Power Resume</source>
        <comment>msg 457</comment>
        <translation>断电断点加工</translation>
    </message>
    <message>
        <source>Pause Resume</source>
        <comment>msg 458</comment>
        <translation>暂停断点加工</translation>
    </message>
    <message>
        <source>Breakpoint find out, do you want to start ?/[%s]</source>
        <comment>msg 860</comment>
        <translation>文件扫描并定位成功,是否进行启动加工?/[%s]</translation>
    </message>
    <message>
        <source>No program loaded: load one on the Program page</source>
        <translation>未载入程序: 请在文件管理页面载入</translation>
    </message>
    <message>
        <source>Start line no.:</source>
        <comment>msg 94</comment>
        <translation>起始加工行号:</translation>
    </message>
    <message>
        <source>Line %1 is not in the program</source>
        <translation>程序中没有第%1行</translation>
    </message>
    <message>
        <source>No break point is kept in the machine folder</source>
        <translation>机床目录中没有保存的断点</translation>
    </message>
    <message>
        <source>No paused run to resume (PAUSE, then RESET)</source>
        <translation>没有可恢复的暂停断点 (先暂停, 再复位)</translation>
    </message>
    <message>
        <source>BreakPoint%d:%s L:%d</source>
        <comment>msg 102</comment>
        <translation>断点记录%d:%s第%d行</translation>
    </message>
    <message>
        <source>Current file:</source>
        <comment>msg 876</comment>
        <translation>当前加工程序:</translation>
    </message>
</context>
<context>
    <name>m350::ui::BreakageMonitorPage</name>
    <message>
        <source>Breakage Monitor</source>
        <translation>破损监测</translation>
    </message>
    <message>
        <source>Tool Table</source>
        <translation>刀具表</translation>
    </message>
    <message>
        <source>Current tool:</source>
        <translation>当前刀具:</translation>
    </message>
    <message>
        <source>Spindle load:</source>
        <translation>主轴负载:</translation>
    </message>
    <message>
        <source>Register:</source>
        <translation>寄存器:</translation>
    </message>
    <message>
        <source>Lambda (param 4127):</source>
        <translation>λ(参数4127):</translation>
    </message>
    <message>
        <source>Limits:</source>
        <translation>限值:</translation>
    </message>
    <message>
        <source>Rule:</source>
        <translation>判定:</translation>
    </message>
    <message>
        <source>Alarm:</source>
        <translation>报警:</translation>
    </message>
    <message>
        <source>Load %</source>
        <translation>负载率 %</translation>
    </message>
    <message>
        <source>Lower limit</source>
        <translation>下限</translation>
    </message>
    <message>
        <source>Upper limit</source>
        <translation>上限</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>时间(秒)</translation>
    </message>
    <message>
        <source>Load (%)</source>
        <translation>负载率(%)</translation>
    </message>
    <message>
        <source>Load% = L / 32767 x lambda, kept x100 in a 16-bit register. Limits per tool in spindle-load.toml; the lower one counts only while the tool cuts.</source>
        <translation>负载率 = L / 32767 × λ,放大100倍存入16位寄存器。各刀具的限值在 spindle-load.toml 中;下限只在切削时判定。</translation>
    </message>
    <message>
        <source>None</source>
        <translation>无</translation>
    </message>
    <message>
        <source>This machine has no spindle load model ([spindle_load] in machine.toml).</source>
        <translation>本机床没有主轴负载模型(machine.toml 的 [spindle_load])。</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>none for this tool</source>
        <translation>本刀具未设限值</translation>
    </message>
    <message>
        <source>%1 samples in a row out of the limits, one every %2 ms</source>
        <translation>连续%1次采样超出限值报警,每%2毫秒采样一次</translation>
    </message>
</context>
<context>
    <name>m350::ui::CompactDro</name>
    <message>
        <source>Mach</source>
        <comment>msg 34</comment>
        <translation>机械坐标</translation>
    </message>
    <message>
        <source>Abs</source>
        <comment>msg 35</comment>
        <translation>工件坐标</translation>
    </message>
</context>
<context>
    <name>m350::ui::CoordPage</name>
    <message>
        <source>Coord Set</source>
        <comment>msg 319</comment>
        <translation>坐标管理</translation>
    </message>
    <message>
        <source>Offset</source>
        <comment>msg 87</comment>
        <translation>公共偏置</translation>
    </message>
    <message>
        <source>G92</source>
        <comment>msg 232</comment>
        <translation>G92坐标系</translation>
    </message>
    <message>
        <source>1:[Knob]Move the cursor,[Enter]modify.</source>
        <comment>msg 997</comment>
        <translation>1:[旋钮]键切换输入焦点,[确认]键修改偏置.</translation>
    </message>
    <message>
        <source>2:[Deeper] and [Move Up]Modified Z ext-offset.</source>
        <comment>msg 998</comment>
        <translation>2:[加深]和[抬高]功能仅对公共偏置Z轴数据有效.</translation>
    </message>
    <message>
        <source>Clear 4th</source>
        <comment>msg 507</comment>
        <translation>设置4th</translation>
    </message>
    <message>
        <source>Clear 5th</source>
        <comment>msg 508</comment>
        <translation>设置5th</translation>
    </message>
    <message>
        <source>Select Coord</source>
        <comment>msg 500</comment>
        <translation>选择坐标系</translation>
    </message>
    <message>
        <source>Clear X</source>
        <comment>msg 501</comment>
        <translation>设置X</translation>
    </message>
    <message>
        <source>Clear Y</source>
        <comment>msg 502</comment>
        <translation>设置Y</translation>
    </message>
    <message>
        <source>Clear Z</source>
        <comment>msg 503</comment>
        <translation>设置Z</translation>
    </message>
    <message>
        <source>Z Step</source>
        <comment>msg 504</comment>
        <translation>Z轴调整值</translation>
    </message>
    <message>
        <source>Deeper</source>
        <comment>msg 505</comment>
        <translation>加深</translation>
    </message>
    <message>
        <source>Move up</source>
        <comment>msg 506</comment>
        <translation>抬高</translation>
    </message>
    <message>
        <source>Select the work system: 0 = G92, 1-6 = G54-G59</source>
        <translation>选择坐标系: 0 = G92, 1-6 = G54-G59</translation>
    </message>
    <message>
        <source>Is not G54-G59 coordinate!</source>
        <comment>msg 987</comment>
        <translation>当前坐标系不是(G54-G59)工件坐标系!</translation>
    </message>
    <message>
        <source>Z Step:</source>
        <comment>msg 999</comment>
        <translation>Z轴加深和抬高距离:</translation>
    </message>
    <message>
        <source>Step distance must be a number from 0.001 to 100</source>
        <translation>寸动距离须为0.001至100之间的数值</translation>
    </message>
    <message>
        <source>Axis Abs pos:</source>
        <comment>msg 93</comment>
        <translation>轴当前点工件坐标系坐标:</translation>
    </message>
    <message>
        <source>Not a number: %1</source>
        <translation>不是数字: %1</translation>
    </message>
</context>
<context>
    <name>m350::ui::CustomKeysPage</name>
    <message>
        <source>Manual</source>
        <comment>msg 318</comment>
        <translation>定制功能</translation>
    </message>
    <message>
        <source>%1 runs M#1996 (#1996 = M250-M263 for K01-K14). UP/DOWN/LEFT/RIGHT: key, ENTER: press.</source>
        <translation>%1 执行 M#1996 (K01-K14 对应 #1996 = M250-M263)。上/下/左/右:选键,回车:按下。</translation>
    </message>
    <message>
        <source>No %1 in the machine folder: a key runs its M code (M250-M263) as MDI. UP/DOWN/LEFT/RIGHT: key, ENTER: press.</source>
        <translation>机床文件夹中没有 %1:按键以MDI方式执行其M代码(M250-M263)。上/下/左/右:选键,回车:按下。</translation>
    </message>
    <message>
        <source>Manual</source>
        <comment>msg 480</comment>
        <translation>手动操作</translation>
    </message>
    <message>
        <source>Presses the selected FUNC key</source>
        <translation>按下所选扩展按键</translation>
    </message>
    <message>
        <source>CAM</source>
        <comment>msg 482</comment>
        <translation>CAM加工</translation>
    </message>
    <message>
        <source>The CAM wizard pages (CAM.nc) are not simulated</source>
        <translation>模拟器不提供CAM加工向导页面(CAM.nc)</translation>
    </message>
</context>
<context>
    <name>m350::ui::GraphicsPage</name>
    <message>
        <source>Simulation</source>
        <comment>msg 312</comment>
        <translation>图形显示</translation>
    </message>
    <message>
        <source>Top View</source>
        <translation>俯视</translation>
    </message>
    <message>
        <source>Front View</source>
        <translation>正视</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>全图</translation>
    </message>
    <message>
        <source>Zoom In</source>
        <translation>放大</translation>
    </message>
    <message>
        <source>Zoom Out</source>
        <translation>缩小</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>返回</translation>
    </message>
</context>
<context>
    <name>m350::ui::IoPage</name>
    <message>
        <source>IO</source>
        <comment>msg 303</comment>
        <translation>IO状态</translation>
    </message>
    <message>
        <source>Stat</source>
        <comment>msg 493</comment>
        <translation>状态</translation>
    </message>
    <message>
        <source>Port Name</source>
        <comment>msg 130</comment>
        <translation>端口名称</translation>
    </message>
    <message>
        <source>Enable</source>
        <comment>msg 131</comment>
        <translation>使能</translation>
    </message>
    <message>
        <source>Pin No.</source>
        <comment>msg 132</comment>
        <translation>管脚编号</translation>
    </message>
    <message>
        <source>Polarity</source>
        <comment>msg 133</comment>
        <translation>极性</translation>
    </message>
    <message>
        <source>Inputs IN01-IN24</source>
        <translation>输入 IN01-IN24</translation>
    </message>
    <message>
        <source>Outputs OUT01-OUT21</source>
        <translation>输出 OUT01-OUT21</translation>
    </message>
    <message>
        <source>Simulator only: a fault a trainer puts on the selected input</source>
        <translation>仅模拟器: 培训师给选中输入口设置的故障</translation>
    </message>
    <message>
        <source>The IO test screens drive real hardware; the simulator has none</source>
        <translation>IO测试界面驱动真实硬件, 模拟器没有</translation>
    </message>
    <message>
        <source>Out Open</source>
        <comment>msg 396</comment>
        <translation>输出开</translation>
    </message>
    <message>
        <source>Out Close</source>
        <comment>msg 397</comment>
        <translation>输出关</translation>
    </message>
    <message>
        <source>Change Polarity</source>
        <comment>msg 399</comment>
        <translation>修改极性</translation>
    </message>
    <message>
        <source>Test</source>
        <comment>msg 401</comment>
        <translation>测试界面</translation>
    </message>
    <message>
        <source>Sim: stuck 0</source>
        <translation>模拟:卡死0</translation>
    </message>
    <message>
        <source>Sim: stuck 1</source>
        <translation>模拟:卡死1</translation>
    </message>
    <message>
        <source>Sim: slow 2 s</source>
        <translation>模拟:迟缓2秒</translation>
    </message>
    <message>
        <source>Sim: bouncing</source>
        <translation>模拟:抖动</translation>
    </message>
    <message>
        <source>Sim: clear fault</source>
        <translation>模拟:清除故障</translation>
    </message>
    <message>
        <source>Sim: press</source>
        <translation>模拟:按下</translation>
    </message>
    <message>
        <source>Simulator only: the selected input reads its active level for 0.3 s, as a key pressed</source>
        <translation>仅模拟:所选输入以有效电平保持0.3秒,如同按下按键</translation>
    </message>
    <message>
        <source>Select a port first (UP/DOWN)</source>
        <translation>请先选择端口(上/下键)</translation>
    </message>
    <message>
        <source>Select an output port first (UP/DOWN)</source>
        <translation>请先选择输出端口(上/下键)</translation>
    </message>
    <message>
        <source>T%1 is in the spindle: releasing the drawbar drops it. Release it?</source>
        <translation>主轴上有刀具T%1,松刀后刀具会掉落,是否松刀?</translation>
    </message>
    <message>
        <source>Select an input port first (UP/DOWN)</source>
        <translation>请先选择输入端口(上/下键)</translation>
    </message>
    <message>
        <source>Yes</source>
        <translation>是</translation>
    </message>
    <message>
        <source>No</source>
        <translation>否</translation>
    </message>
    <message>
        <source>Sensor watchdog: %1 awaited at %2 for %3 s (%4:%5)</source>
        <translation>传感器监视: 等待 %1 为 %2, 已 %3 秒 (%4:%5)</translation>
    </message>
    <message>
        <source>Sensor watchdog: %1</source>
        <translation>传感器监视: %1</translation>
    </message>
</context>
<context>
    <name>m350::ui::LevelPrompt</name>
    <message>
        <source>Pls input super admi or hight user's rights:</source>
        <comment>msg 925</comment>
        <translation>请输入[超级管理员]及以上密码切换用户权限:</translation>
    </message>
    <message>
        <source>Pls input admi or hight user's rights:</source>
        <comment>msg 924</comment>
        <translation>请输入[管理员]及以上密码切换用户权限:</translation>
    </message>
    <message>
        <source>Pls input operator or hight user's rights:</source>
        <comment>msg 923</comment>
        <translation>请输入[操作员]及以上密码切换用户权限:</translation>
    </message>
    <message>
        <source>Incorrect password!</source>
        <comment>msg 905</comment>
        <translation>解锁密码输入错误!</translation>
    </message>
    <message>
        <source>User level: %1</source>
        <translation>用户权限: %1</translation>
    </message>
    <message>
        <source>Change user level (0 %1, 1 %2, 2 %3, 3 %4):</source>
        <translation>切换用户权限 (0 %1, 1 %2, 2 %3, 3 %4):</translation>
    </message>
    <message>
        <source>Enter 0, 1, 2 or 3</source>
        <translation>请输入 0、1、2 或 3</translation>
    </message>
    <message>
        <source>Rights is limited,pls shift user's rights:</source>
        <comment>msg 934</comment>
        <translation>权限不足!请输入密码切换用户权限:</translation>
    </message>
    <message>
        <source>Pls input new password:</source>
        <comment>msg 922</comment>
        <translation>请输入新密码:</translation>
    </message>
    <message>
        <source>The No. of characters &lt; 6,pls input again!</source>
        <comment>msg 918</comment>
        <translation>输入的字符个数小于6个,请重新输入!</translation>
    </message>
    <message>
        <source>Pls input password again:</source>
        <comment>msg 921</comment>
        <translation>请再次输入新密码:</translation>
    </message>
    <message>
        <source>Two entries are not the same,pls input again!</source>
        <comment>msg 919</comment>
        <translation>两次输入密码不一致,请重新输入!</translation>
    </message>
    <message>
        <source>Successfully modified!</source>
        <comment>msg 920</comment>
        <translation>密码修改成功!</translation>
    </message>
</context>
<context>
    <name>m350::ui::LogPage</name>
    <message>
        <source>System Log</source>
        <comment>msg 304</comment>
        <translation>系统日志</translation>
    </message>
    <message>
        <source>Time</source>
        <comment>msg 100</comment>
        <translation>时刻</translation>
    </message>
    <message>
        <source>Event</source>
        <comment>msg 101</comment>
        <translation>事件明细</translation>
    </message>
    <message>
        <source>Start working</source>
        <comment>msg 112</comment>
        <translation>开始加工</translation>
    </message>
    <message>
        <source>Resume</source>
        <comment>msg 113</comment>
        <translation>恢复加工</translation>
    </message>
    <message>
        <source>Pause</source>
        <comment>msg 114</comment>
        <translation>暂停加工</translation>
    </message>
    <message>
        <source>MDI</source>
        <comment>msg 129</comment>
        <translation>MDI运行</translation>
    </message>
    <message>
        <source>Hook file run</source>
        <translation>执行系统宏文件</translation>
    </message>
    <message>
        <source>Probe</source>
        <comment>msg 108</comment>
        <translation>对刀操作</translation>
    </message>
    <message>
        <source>Home All Axes</source>
        <comment>msg 107</comment>
        <translation>全轴寻零操作</translation>
    </message>
    <message>
        <source>Axis mach zero</source>
        <comment>msg 119</comment>
        <translation>轴寻零操作</translation>
    </message>
    <message>
        <source>All axis clear</source>
        <comment>msg 120</comment>
        <translation>全轴置零操作</translation>
    </message>
    <message>
        <source>Axis Coord set</source>
        <comment>msg 118</comment>
        <translation>轴工件坐标系设定</translation>
    </message>
    <message>
        <source>All axes go to zero</source>
        <comment>msg 115</comment>
        <translation>全轴回零操作</translation>
    </message>
    <message>
        <source>Axes Middle</source>
        <comment>msg 109</comment>
        <translation>轴分中操作</translation>
    </message>
    <message>
        <source>Start Simulating</source>
        <comment>msg 111</comment>
        <translation>开始仿真</translation>
    </message>
    <message>
        <source>SL over</source>
        <comment>msg 125</comment>
        <translation>仿真结束</translation>
    </message>
    <message>
        <source>Select file</source>
        <comment>msg 110</comment>
        <translation>选取加工文件:</translation>
    </message>
    <message>
        <source>Line start</source>
        <comment>msg 126</comment>
        <translation>指定行加工</translation>
    </message>
    <message>
        <source>Break run</source>
        <comment>msg 128</comment>
        <translation>断点加工</translation>
    </message>
    <message>
        <source>RESET</source>
        <comment>msg 22</comment>
        <translation>复位</translation>
    </message>
    <message>
        <source>ESP</source>
        <comment>msg 749</comment>
        <translation>急停启动</translation>
    </message>
    <message>
        <source>ERROR</source>
        <comment>msg 23</comment>
        <translation>故障</translation>
    </message>
    <message>
        <source>Parameter changed</source>
        <translation>参数修改</translation>
    </message>
    <message>
        <source>Parameter changed (Guest)</source>
        <translation>参数修改(访客)</translation>
    </message>
    <message>
        <source>Parameter changed (Operator)</source>
        <translation>参数修改(操作员)</translation>
    </message>
    <message>
        <source>Parameter changed (Admin)</source>
        <translation>参数修改(管理员)</translation>
    </message>
    <message>
        <source>Parameter changed (Super)</source>
        <translation>参数修改(超级管理)</translation>
    </message>
    <message>
        <source>passwords.toml cannot be trusted: only Guest opens until it is repaired</source>
        <translation>passwords.toml 不可信: 修复前只能以访客登录</translation>
    </message>
    <message>
        <source>Passwords reset to their defaults (m350-sim reset-passwords)</source>
        <translation>密码已恢复为默认值(m350-sim reset-passwords)</translation>
    </message>
    <message>
        <source>Variable changed</source>
        <translation>变量修改</translation>
    </message>
    <message>
        <source>Output switched</source>
        <translation>输出切换</translation>
    </message>
    <message>
        <source>Simulator: input fault</source>
        <translation>模拟器: 输入口故障</translation>
    </message>
    <message>
        <source>User level changed</source>
        <translation>用户权限切换</translation>
    </message>
    <message>
        <source>Clear Record</source>
        <comment>msg 548</comment>
        <translation>清除加工记录</translation>
    </message>
    <message>
        <source>Tool table changed</source>
        <translation>刀具表修改</translation>
    </message>
    <message>
        <source>Tool touched off</source>
        <translation>刀长设定</translation>
    </message>
    <message>
        <source>Set target tool No.:</source>
        <comment>msg 883</comment>
        <translation>设置目标刀具号:</translation>
    </message>
    <message>
        <source>Tool life reset</source>
        <translation>刀具寿命清零</translation>
    </message>
    <message>
        <source>DPRNT output</source>
        <translation>DPRNT输出</translation>
    </message>
    <message>
        <source>DPRNT output reached its limit; dprnt.txt keeps the first and the last records</source>
        <translation>DPRNT输出达到上限，dprnt.txt 只保留最前和最后的记录</translation>
    </message>
    <message>
        <source>DPRNT records not logged (sent faster than the log takes them)</source>
        <translation>未记入日志的DPRNT记录（发送快于日志记录）</translation>
    </message>
    <message>
        <source>The System Log is not saved: %1</source>
        <translation>系统日志未保存：%1</translation>
    </message>
</context>
<context>
    <name>m350::ui::MachineView</name>
    <message>
        <source>X-Y  Top view</source>
        <translation>X-Y  俯视图</translation>
    </message>
    <message>
        <source>X-Z  Front view</source>
        <translation>X-Z  正视图</translation>
    </message>
    <message>
        <source>Building the preview...</source>
        <translation>正在生成图形...</translation>
    </message>
    <message>
        <source>%1 moves</source>
        <translation>%1 段轨迹</translation>
    </message>
    <message>
        <source>Simplified to %1 mm (memory budget)</source>
        <translation>已简化至 %1 mm（内存上限）</translation>
    </message>
    <message>
        <source>The program has errors: no path</source>
        <translation>程序有错误：无轨迹</translation>
    </message>
    <message>
        <source>No program path</source>
        <translation>无程序轨迹</translation>
    </message>
</context>
<context>
    <name>m350::ui::MainWindow</name>
    <message>
        <source>Recording stopped: %1</source>
        <translation>录制已停止: %1</translation>
    </message>
    <message>
        <source>Input the step distance (mm):</source>
        <translation>输入寸动距离(mm):</translation>
    </message>
    <message>
        <source>Step distance must be a number from 0.001 to 100</source>
        <translation>寸动距离须为0.001至100之间的数值</translation>
    </message>
    <message>
        <source>Pause</source>
        <comment>msg 114</comment>
        <translation>暂停加工</translation>
    </message>
    <message>
        <source>Waiting for %1 = %2 for %3 s (%4:%5)</source>
        <translation>等待 %1 = %2, 已等待 %3 秒 (%4:%5)</translation>
    </message>
    <message>
        <source>Go to home?</source>
        <comment>msg 140</comment>
        <translation>是否进行开机寻零操作?</translation>
    </message>
    <message>
        <source>Set target tool No.:</source>
        <comment>msg 883</comment>
        <translation>设置目标刀具号:</translation>
    </message>
    <message>
        <source>Recording stopped</source>
        <translation>操作录制已停止</translation>
    </message>
    <message>
        <source>Record operator actions</source>
        <translation>录制操作</translation>
    </message>
    <message>
        <source>%1 is inside the machine folder %2: refused, nothing was written</source>
        <translation>%1 在机床文件夹 %2 内: 已拒绝, 未写入任何内容</translation>
    </message>
    <message>
        <source>%1 is the loaded program: refused, nothing was written</source>
        <translation>%1 是已加载的程序: 已拒绝, 未写入任何内容</translation>
    </message>
    <message>
        <source>%1 is a folder, not a file: refused, nothing was written</source>
        <translation>%1 是文件夹, 不是文件: 已拒绝, 未写入任何内容</translation>
    </message>
    <message>
        <source>%1 is a socket, not a file: refused, nothing was written</source>
        <translation>%1 是套接字, 不是文件: 已拒绝, 未写入任何内容</translation>
    </message>
    <message>
        <source>%1 is a disk (block device), not a file: refused, nothing was written</source>
        <translation>%1 是磁盘(块设备), 不是文件: 已拒绝, 未写入任何内容</translation>
    </message>
    <message>
        <source>%1: its folder does not exist or is not a folder: refused, nothing was written</source>
        <translation>%1: 所在文件夹不存在或不是文件夹: 已拒绝, 未写入任何内容</translation>
    </message>
    <message>
        <source>M350 Studio</source>
        <translation>M350 Studio</translation>
    </message>
    <message>
        <source>Panel</source>
        <translation>面板</translation>
    </message>
    <message>
        <source>Record operator actions...</source>
        <translation>录制操作...</translation>
    </message>
    <message>
        <source>MPG RUN: reverse wheel retraces the path</source>
        <translation>手轮试切: 反摇沿原路径回退</translation>
    </message>
    <message>
        <source>Import controller backup...</source>
        <translation>导入控制器备份...</translation>
    </message>
</context>
<context>
    <name>m350::ui::MdiPage</name>
    <message>
        <source>MDI</source>
        <comment>msg 11</comment>
        <translation>MDI</translation>
    </message>
    <message>
        <source>[Knob]Move the cursor,[Enter]Edit current line,[Execute]Execute current line.</source>
        <comment>msg 962</comment>
        <translation>[旋钮]键移动选中标识条,按[确认]键编辑当前选中指令,按[执行]键执行对应指令.</translation>
    </message>
    <message>
        <source>Execute(1)</source>
        <comment>msg 372</comment>
        <translation>执行(1)</translation>
    </message>
    <message>
        <source>Execute(2)</source>
        <comment>msg 373</comment>
        <translation>执行(2)</translation>
    </message>
    <message>
        <source>Execute(3)</source>
        <comment>msg 374</comment>
        <translation>执行(3)</translation>
    </message>
    <message>
        <source>Execute(4)</source>
        <comment>msg 375</comment>
        <translation>执行(4)</translation>
    </message>
    <message>
        <source>Execute(5)</source>
        <comment>msg 376</comment>
        <translation>执行(5)</translation>
    </message>
    <message>
        <source>Execute(6)</source>
        <comment>msg 377</comment>
        <translation>执行(6)</translation>
    </message>
    <message>
        <source>MDI line %1 is empty</source>
        <translation>MDI第%1行为空</translation>
    </message>
    <message>
        <source>Execute(%1)</source>
        <translation>执行(%1)</translation>
    </message>
    <message>
        <source>BUSY</source>
        <comment>msg 21</comment>
        <translation>运行</translation>
    </message>
    <message>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <source>ALARM</source>
        <comment>msg 24</comment>
        <translation>警告</translation>
    </message>
</context>
<context>
    <name>m350::ui::MiddlePage</name>
    <message>
        <source>Middle</source>
        <comment>msg 321</comment>
        <translation>分中</translation>
    </message>
    <message>
        <source>Set 1</source>
        <comment>msg 524</comment>
        <translation>记录1</translation>
    </message>
    <message>
        <source>Set 2</source>
        <comment>msg 525</comment>
        <translation>记录2</translation>
    </message>
    <message>
        <source>Middle</source>
        <comment>msg 526</comment>
        <translation>分中</translation>
    </message>
    <message>
        <source>4pts</source>
        <comment>msg 529</comment>
        <translation>手动分中</translation>
    </message>
    <message>
        <source>Set X</source>
        <comment>msg 512</comment>
        <translation>记录X</translation>
    </message>
    <message>
        <source>Middle X</source>
        <comment>msg 513</comment>
        <translation>分中X</translation>
    </message>
    <message>
        <source>Set Y</source>
        <comment>msg 514</comment>
        <translation>记录Y</translation>
    </message>
    <message>
        <source>Middle Y</source>
        <comment>msg 515</comment>
        <translation>分中Y</translation>
    </message>
    <message>
        <source>3Pts</source>
        <comment>msg 517</comment>
        <translation>圆弧分中</translation>
    </message>
    <message>
        <source>Press [Set X] at the first side first</source>
        <translation>请先在工件一侧按[记录X]</translation>
    </message>
    <message>
        <source>Press [Set Y] at the first side first</source>
        <translation>请先在工件一侧按[记录Y]</translation>
    </message>
    <message>
        <source>Record two points of the circle first ([Set 1], [Set 2])</source>
        <translation>请先记录圆周上两点([记录1], [记录2])</translation>
    </message>
    <message>
        <source>The three points lie on a line: no circle through them</source>
        <translation>三点共线: 无法确定圆心</translation>
    </message>
    <message>
        <source>Arc 3 pts:</source>
        <comment>msg 964</comment>
        <translation>圆弧三点分中:</translation>
    </message>
    <message>
        <source>First pts:</source>
        <comment>msg 968</comment>
        <translation>第一组记录:</translation>
    </message>
    <message>
        <source>Second pts:</source>
        <comment>msg 969</comment>
        <translation>第二组记录:</translation>
    </message>
    <message>
        <source>Third pts:</source>
        <comment>msg 970</comment>
        <translation>第三组记录:</translation>
    </message>
    <message>
        <source>Center:</source>
        <comment>msg 971</comment>
        <translation>分中值:</translation>
    </message>
    <message>
        <source>1:Move to the first point and press [Set 1];</source>
        <comment>msg 965</comment>
        <translation>1:移动到圆周上一点,按[记录1]键,系统将当前机械坐标作为第一组坐标;</translation>
    </message>
    <message>
        <source>2:Move to the second point and press [Set 2];</source>
        <comment>msg 966</comment>
        <translation>2:移动到圆周上另一点,按[记录2]键,系统将当前机械坐标作为第二组坐标;</translation>
    </message>
    <message>
        <source>3:Move to the third point and press[Middle],get center of arc and set it to zero;</source>
        <comment>msg 967</comment>
        <translation>3:移动到圆周上第三点,按[分中]键,由前两组坐标和当前机械坐标计算圆心并设为工件零点;</translation>
    </message>
    <message>
        <source>4 Pts:</source>
        <comment>msg 972</comment>
        <translation>手动分中:</translation>
    </message>
    <message>
        <source>Px1:</source>
        <comment>msg 976</comment>
        <translation>X轴记录1:</translation>
    </message>
    <message>
        <source>Px2:</source>
        <comment>msg 977</comment>
        <translation>X轴记录2:</translation>
    </message>
    <message>
        <source>Pxm:</source>
        <comment>msg 978</comment>
        <translation>分中值X:</translation>
    </message>
    <message>
        <source>Py1:</source>
        <comment>msg 979</comment>
        <translation>Y轴记录1:</translation>
    </message>
    <message>
        <source>Py2</source>
        <comment>msg 980</comment>
        <translation>Y轴记录2</translation>
    </message>
    <message>
        <source>Pym:</source>
        <comment>msg 981</comment>
        <translation>分中值Y:</translation>
    </message>
    <message>
        <source>Mannal Center Operation(X):</source>
        <comment>msg 973</comment>
        <translation>手动分中操作步骤:</translation>
    </message>
    <message>
        <source>1:Take the tool to the point Px1 and press [Set X] to set;</source>
        <comment>msg 974</comment>
        <translation>1:手动移动刀具到工件的一侧,按[记录]键,记录下当前点的机械位置;</translation>
    </message>
    <message>
        <source>2:Take the tool to the point Px2 and press [Middle X],get  midpoint and set the X zero;</source>
        <comment>msg 975</comment>
        <translation>2:再移动到工件另一侧,按[分中]键,由当前位置和上次位置计算中点坐标并设置为工件零点;</translation>
    </message>
</context>
<context>
    <name>m350::ui::MonitorPage</name>
    <message>
        <source>Monitor</source>
        <comment>msg 300</comment>
        <translation>加工状态</translation>
    </message>
    <message>
        <source>Axis</source>
        <comment>msg 33</comment>
        <translation>轴</translation>
    </message>
    <message>
        <source>Mach</source>
        <comment>msg 34</comment>
        <translation>机械坐标</translation>
    </message>
    <message>
        <source>Abs</source>
        <comment>msg 35</comment>
        <translation>工件坐标</translation>
    </message>
    <message>
        <source>Coord:</source>
        <comment>msg 991</comment>
        <translation>坐标系:</translation>
    </message>
    <message>
        <source>FRO</source>
        <comment>msg 30</comment>
        <translation>进给倍率</translation>
    </message>
    <message>
        <source>SRO</source>
        <comment>msg 31</comment>
        <translation>主轴倍率</translation>
    </message>
    <message>
        <source>SJR</source>
        <comment>msg 32</comment>
        <translation>手动倍率</translation>
    </message>
    <message>
        <source>Feed Rate</source>
        <comment>msg 36</comment>
        <translation>进给速度</translation>
    </message>
    <message>
        <source>Cur Tool</source>
        <comment>msg 46</comment>
        <translation>当前刀具</translation>
    </message>
    <message>
        <source>Total No.</source>
        <comment>msg 47</comment>
        <translation>总加工数</translation>
    </message>
    <message>
        <source>Cur No.</source>
        <comment>msg 48</comment>
        <translation>加工件数</translation>
    </message>
    <message>
        <source>Work Time</source>
        <comment>msg 49</comment>
        <translation>加工时间</translation>
    </message>
    <message>
        <source>INC Distance</source>
        <comment>msg 244</comment>
        <translation>输入寸动距离</translation>
    </message>
    <message>
        <source>X Go Home</source>
        <comment>msg 420</comment>
        <translation>机械X轴回</translation>
    </message>
    <message>
        <source>Y Go Home</source>
        <comment>msg 421</comment>
        <translation>机械Y轴回</translation>
    </message>
    <message>
        <source>Z Go Home</source>
        <comment>msg 422</comment>
        <translation>机械Z轴回</translation>
    </message>
    <message>
        <source>4th Go Home</source>
        <comment>msg 423</comment>
        <translation>机械4th轴回</translation>
    </message>
    <message>
        <source>5th Go Home</source>
        <comment>msg 424</comment>
        <translation>机械5th轴回</translation>
    </message>
    <message>
        <source>All Go Home</source>
        <comment>msg 425</comment>
        <translation>机械全部回</translation>
    </message>
    <message>
        <source>X Go Zero</source>
        <comment>msg 432</comment>
        <translation>工件X轴回</translation>
    </message>
    <message>
        <source>Y Go Zero</source>
        <comment>msg 433</comment>
        <translation>工件Y轴回</translation>
    </message>
    <message>
        <source>Z Go Zero</source>
        <comment>msg 434</comment>
        <translation>工件Z轴回</translation>
    </message>
    <message>
        <source>4th Go Zero</source>
        <comment>msg 435</comment>
        <translation>工件4th轴回</translation>
    </message>
    <message>
        <source>5th Go Zero</source>
        <comment>msg 436</comment>
        <translation>工件5th轴回</translation>
    </message>
    <message>
        <source>All Go Zero</source>
        <comment>msg 437</comment>
        <translation>工件全部回</translation>
    </message>
    <message>
        <source>Clear X</source>
        <comment>msg 444</comment>
        <translation>X清零</translation>
    </message>
    <message>
        <source>Clear Y</source>
        <comment>msg 445</comment>
        <translation>Y清零</translation>
    </message>
    <message>
        <source>Clear Z</source>
        <comment>msg 446</comment>
        <translation>Z清零</translation>
    </message>
    <message>
        <source>Clear 4th</source>
        <comment>msg 447</comment>
        <translation>4th清零</translation>
    </message>
    <message>
        <source>Clear 5th</source>
        <comment>msg 448</comment>
        <translation>5th清零</translation>
    </message>
    <message>
        <source>Clear All</source>
        <comment>msg 449</comment>
        <translation>全部清零</translation>
    </message>
    <message>
        <source>Simulation</source>
        <comment>msg 312</comment>
        <translation>图形显示</translation>
    </message>
    <message>
        <source>Probe</source>
        <comment>msg 313</comment>
        <translation>对刀</translation>
    </message>
    <message>
        <source>Go Work Zero</source>
        <comment>msg 314</comment>
        <translation>回工件原点</translation>
    </message>
    <message>
        <source>Go Home</source>
        <comment>msg 315</comment>
        <translation>回机械原点</translation>
    </message>
    <message>
        <source>Clear</source>
        <comment>msg 316</comment>
        <translation>清零</translation>
    </message>
    <message>
        <source>Break Run</source>
        <comment>msg 317</comment>
        <translation>断点加工</translation>
    </message>
    <message>
        <source>Manual</source>
        <comment>msg 318</comment>
        <translation>定制功能</translation>
    </message>
    <message>
        <source>Coord Set</source>
        <comment>msg 319</comment>
        <translation>坐标管理</translation>
    </message>
    <message>
        <source>MDI</source>
        <comment>msg 320</comment>
        <translation>MDI</translation>
    </message>
    <message>
        <source>Middle</source>
        <comment>msg 321</comment>
        <translation>分中</translation>
    </message>
    <message>
        <source>Work Record</source>
        <comment>msg 322</comment>
        <translation>加工统计</translation>
    </message>
    <message>
        <source>Sort Proces</source>
        <comment>msg 323</comment>
        <translation>序列加工</translation>
    </message>
    <message>
        <source>Not in the simulator</source>
        <translation>模拟器中没有此功能</translation>
    </message>
    <message>
        <source>Homed</source>
        <translation>已回零</translation>
    </message>
    <message>
        <source>Not homed</source>
        <translation>未回零</translation>
    </message>
    <message>
        <source>Servo S</source>
        <comment>msg 38</comment>
        <translation>伺服主轴</translation>
    </message>
    <message>
        <source>Mult S</source>
        <comment>msg 39</comment>
        <translation>多段数主轴</translation>
    </message>
    <message>
        <source>Analog S</source>
        <comment>msg 37</comment>
        <translation>模拟主轴</translation>
    </message>
    <message>
        <source>High</source>
        <comment>msg 873</comment>
        <translation>高速</translation>
    </message>
    <message>
        <source>Low</source>
        <comment>msg 872</comment>
        <translation>低速</translation>
    </message>
</context>
<context>
    <name>m350::ui::PanelText</name>
    <message>
        <source>CONT</source>
        <comment>msg 0</comment>
        <translation>连续</translation>
    </message>
    <message>
        <source>STEP</source>
        <comment>msg 1</comment>
        <translation>寸动</translation>
    </message>
    <message>
        <source>MPG</source>
        <comment>msg 2</comment>
        <translation>手轮</translation>
    </message>
    <message>
        <source>ZERO</source>
        <comment>msg 3</comment>
        <translation>清零</translation>
    </message>
    <message>
        <source>GOTOZ</source>
        <comment>msg 4</comment>
        <translation>回零</translation>
    </message>
    <message>
        <source>HOME</source>
        <comment>msg 5</comment>
        <translation>寻零</translation>
    </message>
    <message>
        <source>PROBE</source>
        <comment>msg 6</comment>
        <translation>对刀</translation>
    </message>
    <message>
        <source>MIDDLE</source>
        <comment>msg 7</comment>
        <translation>分中</translation>
    </message>
    <message>
        <source>AUTO</source>
        <comment>msg 8</comment>
        <translation>自动</translation>
    </message>
    <message>
        <source>SL</source>
        <comment>msg 9</comment>
        <translation>仿真</translation>
    </message>
    <message>
        <source>WHEEL</source>
        <comment>msg 10</comment>
        <translation>试切</translation>
    </message>
    <message>
        <source>MDI</source>
        <comment>msg 11</comment>
        <translation>MDI</translation>
    </message>
    <message>
        <source>READY</source>
        <comment>msg 20</comment>
        <translation>就绪</translation>
    </message>
    <message>
        <source>BUSY</source>
        <comment>msg 21</comment>
        <translation>运行</translation>
    </message>
    <message>
        <source>RESET</source>
        <comment>msg 22</comment>
        <translation>复位</translation>
    </message>
    <message>
        <source>ERROR</source>
        <comment>msg 23</comment>
        <translation>故障</translation>
    </message>
    <message>
        <source>ALARM</source>
        <comment>msg 24</comment>
        <translation>警告</translation>
    </message>
    <message>
        <source>WHEEL</source>
        <comment>msg 25</comment>
        <translation>顺切</translation>
    </message>
    <message>
        <source>WHEEL REV</source>
        <comment>msg 26</comment>
        <translation>逆切</translation>
    </message>
    <message>
        <source>STOP</source>
        <comment>msg 40</comment>
        <translation>停止</translation>
    </message>
    <message>
        <source>FWD</source>
        <comment>msg 41</comment>
        <translation>正转</translation>
    </message>
    <message>
        <source>REV</source>
        <comment>msg 42</comment>
        <translation>反转</translation>
    </message>
    <message>
        <source>JOG</source>
        <comment>msg 43</comment>
        <translation>点动</translation>
    </message>
    <message>
        <source>TAP</source>
        <comment>msg 44</comment>
        <translation>攻丝</translation>
    </message>
    <message>
        <source>PRCE STOP</source>
        <comment>msg 45</comment>
        <translation>准停</translation>
    </message>
    <message>
        <source>deg</source>
        <translation>度</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
</context>
<context>
    <name>m350::ui::ParamPage</name>
    <message>
        <source>Param</source>
        <comment>msg 302</comment>
        <translation>参数管理</translation>
    </message>
    <message>
        <source>Param List</source>
        <comment>msg 384</comment>
        <translation>参数分类</translation>
    </message>
    <message>
        <source>Search</source>
        <comment>msg 385</comment>
        <translation>搜索</translation>
    </message>
    <message>
        <source>Param Backup</source>
        <comment>msg 386</comment>
        <translation>参数备份</translation>
    </message>
    <message>
        <source>Param Restore</source>
        <comment>msg 387</comment>
        <translation>参数恢复</translation>
    </message>
    <message>
        <source>#50-#499</source>
        <comment>msg 388</comment>
        <translation>#50-#499</translation>
    </message>
    <message>
        <source>Factory(N)</source>
        <comment>msg 949</comment>
        <translation>厂商参数(N)</translation>
    </message>
    <message>
        <source>User(O)</source>
        <comment>msg 950</comment>
        <translation>用户参数(O)</translation>
    </message>
    <message>
        <source>User level</source>
        <translation>用户权限</translation>
    </message>
    <message>
        <source>Machine</source>
        <comment>msg 64</comment>
        <translation>机床参数</translation>
    </message>
    <message>
        <source>Manual</source>
        <comment>msg 65</comment>
        <translation>手动参数</translation>
    </message>
    <message>
        <source>Process</source>
        <comment>msg 66</comment>
        <translation>自动参数</translation>
    </message>
    <message>
        <source>Coordinate</source>
        <comment>msg 67</comment>
        <translation>坐标系参数</translation>
    </message>
    <message>
        <source>Spindle</source>
        <comment>msg 68</comment>
        <translation>主轴参数</translation>
    </message>
    <message>
        <source>IO</source>
        <comment>msg 69</comment>
        <translation>IO参数及自定义按键</translation>
    </message>
    <message>
        <source>Home</source>
        <comment>msg 70</comment>
        <translation>零点参数</translation>
    </message>
    <message>
        <source>Probe</source>
        <comment>msg 71</comment>
        <translation>对刀参数</translation>
    </message>
    <message>
        <source>Hard Limit</source>
        <comment>msg 72</comment>
        <translation>硬限位参数</translation>
    </message>
    <message>
        <source>Software limit</source>
        <comment>msg 73</comment>
        <translation>软限位参数</translation>
    </message>
    <message>
        <source>MPG</source>
        <comment>msg 74</comment>
        <translation>手轮参数</translation>
    </message>
    <message>
        <source>External</source>
        <comment>msg 75</comment>
        <translation>扩展参数</translation>
    </message>
    <message>
        <source>Backlash</source>
        <comment>msg 76</comment>
        <translation>补偿参数</translation>
    </message>
    <message>
        <source>Tools</source>
        <comment>msg 77</comment>
        <translation>刀具参数</translation>
    </message>
    <message>
        <source>System</source>
        <comment>msg 78</comment>
        <translation>系统参数</translation>
    </message>
    <message>
        <source>Input ports</source>
        <translation>输入端口</translation>
    </message>
    <message>
        <source>Output ports</source>
        <translation>输出端口</translation>
    </message>
    <message>
        <source>Not on the firmware's pages</source>
        <translation>未列于参数页</translation>
    </message>
    <message>
        <source>No.</source>
        <comment>msg 83</comment>
        <translation>序号</translation>
    </message>
    <message>
        <source>Note</source>
        <comment>msg 84</comment>
        <translation>说明</translation>
    </message>
    <message>
        <source>Value</source>
        <comment>msg 85</comment>
        <translation>数值</translation>
    </message>
    <message>
        <source>Unit</source>
        <comment>msg 86</comment>
        <translation>单位</translation>
    </message>
    <message>
        <source>Macro variables #50-#499, as a program reads them</source>
        <translation>宏变量 #50-#499 (程序读到的值)</translation>
    </message>
    <message>
        <source>(now: %1)</source>
        <translation>(当前: %1)</translation>
    </message>
    <message>
        <source>User:</source>
        <comment>msg 940</comment>
        <translation>修改权限:</translation>
    </message>
    <message>
        <source>Enter sets the selected variable, as a macro's #%1 = value would.</source>
        <translation>[确认] 设置所选变量, 与宏程序 #%1 = 数值 相同。</translation>
    </message>
    <message>
        <source>Param List:</source>
        <comment>msg 941</comment>
        <translation>参数类别:</translation>
    </message>
    <message>
        <source>Details:</source>
        <comment>msg 946</comment>
        <translation>参数说明:</translation>
    </message>
    <message>
        <source>macro #%1, factory value %2</source>
        <translation>宏变量 #%1, 出厂值 %2</translation>
    </message>
    <message>
        <source>Active:</source>
        <comment>msg 947</comment>
        <translation>生效时间:</translation>
    </message>
    <message>
        <source>Immediately</source>
        <comment>msg 913</comment>
        <translation>立即生效</translation>
    </message>
    <message>
        <source>Range:</source>
        <comment>msg 948</comment>
        <translation>设定范围:</translation>
    </message>
    <message>
        <source>[%d]The data entered is illegal!</source>
        <comment>msg 802</comment>
        <translation>[%d]号参数输入的数据非法!</translation>
    </message>
    <message>
        <source>Variable #%1: not a number</source>
        <translation>变量 #%1: 不是数值</translation>
    </message>
    <message>
        <source>Input searching parameter No. :</source>
        <comment>msg 935</comment>
        <translation>请输入搜索的参数编号:</translation>
    </message>
    <message>
        <source>Parameter %1 is not on the parameter pages</source>
        <translation>参数 %1 不在参数页中</translation>
    </message>
    <message>
        <source>File save failed!</source>
        <comment>msg 907</comment>
        <translation>文件生成失败!</translation>
    </message>
    <message>
        <source>Parameters backed up to %1</source>
        <translation>参数已备份至 %1</translation>
    </message>
    <message>
        <source>No backup: %1 does not exist (Param Backup writes it)</source>
        <translation>无备份: %1 不存在 (由参数备份生成)</translation>
    </message>
    <message>
        <source>Restore every parameter from %1?</source>
        <translation>是否从 %1 恢复全部参数?</translation>
    </message>
    <message>
        <source>Parameter restore refused, nothing changed: %1</source>
        <translation>参数恢复被拒绝, 未作任何修改: %1</translation>
    </message>
    <message>
        <source>Parameters restored from %1: %2 changed</source>
        <translation>已从 %1 恢复参数: %2 项改变</translation>
    </message>
    <message>
        <source>; %1 outside their ranges kept as saved</source>
        <translation>; %1 项超出设定范围, 按备份保留</translation>
    </message>
</context>
<context>
    <name>m350::ui::ProbePage</name>
    <message>
        <source>Probe</source>
        <comment>msg 6</comment>
        <translation>对刀</translation>
    </message>
    <message>
        <source>Coord:</source>
        <comment>msg 991</comment>
        <translation>坐标系:</translation>
    </message>
    <message>
        <source>Cur Tool:</source>
        <comment>msg 992</comment>
        <translation>当前刀具号T:</translation>
    </message>
    <message>
        <source>THK Of Probe:</source>
        <comment>msg 993</comment>
        <translation>浮动对刀仪厚度:</translation>
    </message>
    <message>
        <source>Fixed Probe X:</source>
        <comment>msg 994</comment>
        <translation>固定对刀仪X位置:</translation>
    </message>
    <message>
        <source>Fixed Probe Y:</source>
        <comment>msg 995</comment>
        <translation>固定对刀仪Y位置:</translation>
    </message>
    <message>
        <source>Fixed Probe Z:</source>
        <comment>msg 996</comment>
        <translation>固定对刀仪Z位置:</translation>
    </message>
    <message>
        <source>Tool Z offsets (params 930-945)</source>
        <translation>刀具Z偏置 (参数930-945)</translation>
    </message>
    <message>
        <source>Multi-tool selection:</source>
        <comment>msg 864</comment>
        <translation>一键对刀刀具号选择:</translation>
    </message>
    <message>
        <source>1:Before operate [Floating Probe],Pls move tool above the block and set Param 129;</source>
        <comment>msg 984</comment>
        <translation>1:[浮动对刀]操作前请移到对刀仪正上方并设置浮动对刀仪厚度,数值为正值;</translation>
    </message>
    <message>
        <source>2:[Fixed Probe]Input the cutter No.,record the offset of Z axis after tool change;</source>
        <comment>msg 985</comment>
        <translation>2:[固定对刀]录入刀具号,换刀后自动记录刀具号的Z偏置(刀具在对刀仪处的Z机械坐标);</translation>
    </message>
    <message>
        <source>3:[Mult Probe] Probe several tools at one time.select the Tools and press [Mult Probe];</source>
        <comment>msg 986</comment>
        <translation>3:[多刀固定对刀]一次性对多把刀,选择刀具后再次按[多刀固定对刀]执行多刀对刀动作;</translation>
    </message>
    <message>
        <source>Floating Probe</source>
        <comment>msg 468</comment>
        <translation>浮动对刀</translation>
    </message>
    <message>
        <source>Tool Table</source>
        <translation>刀具表</translation>
    </message>
    <message>
        <source>Fixed Probe</source>
        <comment>msg 470</comment>
        <translation>固定对刀</translation>
    </message>
    <message>
        <source>Mult Probe</source>
        <comment>msg 471</comment>
        <translation>多刀固定对刀</translation>
    </message>
    <message>
        <source>XY Teach</source>
        <comment>msg 472</comment>
        <translation>XY位置教导</translation>
    </message>
    <message>
        <source>Z Teach</source>
        <comment>msg 473</comment>
        <translation>Z位置教导</translation>
    </message>
    <message>
        <source>Tool is above the probe sensor?</source>
        <comment>msg 982</comment>
        <translation>当前刀尖位置是否处于对刀块正上方?</translation>
    </message>
    <message>
        <source>Enter the tool number:</source>
        <comment>msg 863</comment>
        <translation>请输入固定对刀的刀具号:</translation>
    </message>
    <message>
        <source>The current tool No. is 0, this operation is invalid!</source>
        <comment>msg 858</comment>
        <translation>当前刀具号为0或非法,操作无效!</translation>
    </message>
    <message>
        <source>Exceeded the maximum!</source>
        <comment>msg 884</comment>
        <translation>输入的刀具号超出刀库容量!</translation>
    </message>
    <message>
        <source>Is the workpiece zero set for the Z axis?</source>
        <comment>msg 983</comment>
        <translation>Z轴工件原点是否已确定?</translation>
    </message>
    <message>
        <source>Pls determine the Z-axis workpiece zero!</source>
        <comment>msg 869</comment>
        <translation>请通过清零或浮动对刀确定Z加工原点!</translation>
    </message>
    <message>
        <source>Select the tools first (arrows move, Enter selects)</source>
        <translation>请先选择刀具(方向键移动, 确认键选择)</translation>
    </message>
    <message>
        <source>One Key probe for the selected tool?</source>
        <comment>msg 866</comment>
        <translation>是否将选中的刀具进行一键对刀操作?</translation>
    </message>
    <message>
        <source>(XY)Mach pos is XY pos of Probe?</source>
        <comment>msg 148</comment>
        <translation>当前点(XY)机械位置作为固定对刀仪XY位置?</translation>
    </message>
    <message>
        <source>(Z)Mach pos is Z pos of Probe?</source>
        <comment>msg 149</comment>
        <translation>当前点(Z)机械位置作为固定对刀仪Z位置?</translation>
    </message>
    <message>
        <source>Probing: %1:%2</source>
        <translation>对刀中: %1:%2</translation>
    </message>
</context>
<context>
    <name>m350::ui::ProgramEditor</name>
    <message>
        <source>File is too large to edit</source>
        <comment>msg 137</comment>
        <translation>文件过大,无法进行编辑操作!</translation>
    </message>
    <message>
        <source>Current File:</source>
        <comment>msg 953</comment>
        <translation>当前编辑文件:</translation>
    </message>
    <message>
        <source>... %1 more</source>
        <translation>... 另有 %1 处</translation>
    </message>
</context>
<context>
    <name>m350::ui::ProgramList</name>
    <message>
        <source>Local Disk(O)</source>
        <comment>msg 959</comment>
        <translation>本地程序(O)</translation>
    </message>
    <message>
        <source>U Disk(N)</source>
        <comment>msg 960</comment>
        <translation>U盘程序(N)</translation>
    </message>
    <message>
        <source>System disk (macro libraries)</source>
        <translation>系统盘(宏程序库)</translation>
    </message>
    <message>
        <source>Name</source>
        <comment>msg 80</comment>
        <translation>名称</translation>
    </message>
    <message>
        <source>Size</source>
        <comment>msg 81</comment>
        <translation>大小</translation>
    </message>
    <message>
        <source>Modify time</source>
        <comment>msg 82</comment>
        <translation>修改时间</translation>
    </message>
    <message>
        <source>Cur Path:</source>
        <comment>msg 952</comment>
        <translation>当前路径:</translation>
    </message>
    <message>
        <source>EXT</source>
        <comment>msg 757</comment>
        <translation>后缀</translation>
    </message>
    <message>
        <source>DATE</source>
        <comment>msg 758</comment>
        <translation>日期</translation>
    </message>
    <message>
        <source>NAME</source>
        <comment>msg 756</comment>
        <translation>名称</translation>
    </message>
    <message>
        <source>Free Space:</source>
        <comment>msg 951</comment>
        <translation>磁盘剩余空间:</translation>
    </message>
    <message>
        <source>Sort:</source>
        <comment>msg 759</comment>
        <translation>排序:</translation>
    </message>
</context>
<context>
    <name>m350::ui::ProgramPage</name>
    <message>
        <source>Program</source>
        <comment>msg 301</comment>
        <translation>文件管理</translation>
    </message>
    <message>
        <source>Not in the simulator</source>
        <translation>模拟器中没有此功能</translation>
    </message>
    <message>
        <source>Save Exit</source>
        <comment>msg 336</comment>
        <translation>保存退出</translation>
    </message>
    <message>
        <source>Find Line</source>
        <comment>msg 337</comment>
        <translation>查找行</translation>
    </message>
    <message>
        <source>Del Line</source>
        <comment>msg 338</comment>
        <translation>删除行</translation>
    </message>
    <message>
        <source>CAM</source>
        <comment>msg 340</comment>
        <translation>图形加工向导</translation>
    </message>
    <message>
        <source>Teaching</source>
        <comment>msg 341</comment>
        <translation>教导</translation>
    </message>
    <message>
        <source>Speed %1</source>
        <translation>速度 %1</translation>
    </message>
    <message>
        <source>Simulate</source>
        <comment>msg 332</comment>
        <translation>仿真</translation>
    </message>
    <message>
        <source>Esc</source>
        <comment>msg 939</comment>
        <translation>退出</translation>
    </message>
    <message>
        <source>The macro libraries are edited here, not deleted, renamed or run</source>
        <translation>宏程序库在此只能编辑, 不能删除、重命名或运行</translation>
    </message>
    <message>
        <source>Copy To Local</source>
        <comment>msg 958</comment>
        <translation>拷贝到本地</translation>
    </message>
    <message>
        <source>Copy To U Disk</source>
        <comment>msg 327</comment>
        <translation>拷贝到U盘</translation>
    </message>
    <message>
        <source>Switch disks</source>
        <comment>msg 324</comment>
        <translation>切换磁盘</translation>
    </message>
    <message>
        <source>Del</source>
        <comment>msg 325</comment>
        <translation>删除</translation>
    </message>
    <message>
        <source>Rename</source>
        <comment>msg 326</comment>
        <translation>重命名</translation>
    </message>
    <message>
        <source>New</source>
        <comment>msg 328</comment>
        <translation>新建</translation>
    </message>
    <message>
        <source>Edit</source>
        <comment>msg 329</comment>
        <translation>编辑</translation>
    </message>
    <message>
        <source>Copy</source>
        <comment>msg 330</comment>
        <translation>拷贝文件</translation>
    </message>
    <message>
        <source>Paste</source>
        <comment>msg 331</comment>
        <translation>粘贴文件</translation>
    </message>
    <message>
        <source>Load NC</source>
        <comment>msg 333</comment>
        <translation>NC读取</translation>
    </message>
    <message>
        <source>Clear local</source>
        <comment>msg 334</comment>
        <translation>清除本地</translation>
    </message>
    <message>
        <source>Sort</source>
        <comment>msg 335</comment>
        <translation>排序</translation>
    </message>
    <message>
        <source>Select file</source>
        <comment>msg 110</comment>
        <translation>选取加工文件:</translation>
    </message>
    <message>
        <source>File save failed!</source>
        <comment>msg 907</comment>
        <translation>文件生成失败!</translation>
    </message>
    <message>
        <source>Pls input searching line No:</source>
        <comment>msg 894</comment>
        <translation>请输入查找的行号:</translation>
    </message>
    <message>
        <source>[Enter] to save,[Esc] is not to save.</source>
        <comment>msg 893</comment>
        <translation>[确认]保存修改;[退出]不保存.</translation>
    </message>
    <message>
        <source>File name is too long!</source>
        <comment>msg 797</comment>
        <translation>文件名过长!</translation>
    </message>
    <message>
        <source>File exists, please re-enter!</source>
        <comment>msg 803</comment>
        <translation>文件名存在请重新输入!</translation>
    </message>
    <message>
        <source>A file name may not begin with a dot or hold / : * ? &lt; &gt; | or a quote</source>
        <translation>文件名不能以点开头, 也不能含有 / : * ? &lt; &gt; | 或引号</translation>
    </message>
    <message>
        <source>Pls enter the file name:</source>
        <comment>msg 804</comment>
        <translation>请输入文件名:</translation>
    </message>
    <message>
        <source>Current file is running,can't delete!</source>
        <comment>msg 871</comment>
        <translation>加工区文件不可删除!</translation>
    </message>
    <message>
        <source>Do you want to delete the selected file?</source>
        <comment>msg 957</comment>
        <translation>是否删除当前选中文件?</translation>
    </message>
    <message>
        <source>file does not exist!</source>
        <comment>msg 842</comment>
        <translation>文件不存在!</translation>
    </message>
    <message>
        <source>Copy successful!</source>
        <comment>msg 955</comment>
        <translation>文件拷贝成功!</translation>
    </message>
    <message>
        <source>Delete all?</source>
        <comment>msg 846</comment>
        <translation>是否删除全部内容?</translation>
    </message>
</context>
<context>
    <name>m350::ui::ProgramWindow</name>
    <message>
        <source>No program loaded</source>
        <translation>未装载程序</translation>
    </message>
    <message>
        <source>%1: cannot be read</source>
        <translation>%1: 无法读取</translation>
    </message>
    <message>
        <source>%1   Line %2</source>
        <translation>%1   行 %2</translation>
    </message>
</context>
<context>
    <name>m350::ui::PromptBox</name>
    <message>
        <source>[Enter] OK    [Esc] Cancel</source>
        <translation>[确认]确定    [取消]退出</translation>
    </message>
</context>
<context>
    <name>m350::ui::RecordPage</name>
    <message>
        <source>Work Record</source>
        <comment>msg 322</comment>
        <translation>加工统计</translation>
    </message>
    <message>
        <source>Clear Record</source>
        <comment>msg 548</comment>
        <translation>清除加工记录</translation>
    </message>
    <message>
        <source>To U Disk</source>
        <comment>msg 549</comment>
        <translation>导出到U盘</translation>
    </message>
    <message>
        <source>Confirm to delete the working record?</source>
        <comment>msg 875</comment>
        <translation>确定要清除加工记录表吗?</translation>
    </message>
    <message>
        <source>%1: cannot write: %2</source>
        <translation>%1: 无法写入: %2</translation>
    </message>
    <message>
        <source>Working record saved to %1</source>
        <translation>加工记录文件已保存至 %1</translation>
    </message>
    <message>
        <source>Current file:</source>
        <comment>msg 876</comment>
        <translation>当前加工程序:</translation>
    </message>
    <message>
        <source>Total No.</source>
        <comment>msg 47</comment>
        <translation>总加工数</translation>
    </message>
    <message>
        <source>Finished No.:</source>
        <comment>msg 878</comment>
        <translation>已加工件数:</translation>
    </message>
    <message>
        <source>Time per:</source>
        <comment>msg 879</comment>
        <translation>单件加工时间:</translation>
    </message>
    <message>
        <source>Total time:</source>
        <comment>msg 880</comment>
        <translation>总加工时间:</translation>
    </message>
    <message>
        <source>Start date:</source>
        <comment>msg 881</comment>
        <translation>开始日期时间:</translation>
    </message>
</context>
<context>
    <name>m350::ui::ReviewBar</name>
    <message>
        <source>%1 / %2 s</source>
        <translation>%1 / %2 秒</translation>
    </message>
    <message>
        <source>End of the attempt</source>
        <translation>练习记录已放完</translation>
    </message>
    <message>
        <source>Next: %1 s hand in</source>
        <translation>下一步：%1 秒 交卷</translation>
    </message>
    <message>
        <source>Next: %1 s %2</source>
        <translation>下一步：%1 秒 %2</translation>
    </message>
    <message>
        <source>key %1</source>
        <translation>按键 %1</translation>
    </message>
    <message>
        <source>key %1 held</source>
        <translation>按住 %1</translation>
    </message>
    <message>
        <source>key %1 let go</source>
        <translation>松开 %1</translation>
    </message>
    <message>
        <source>types "%1"</source>
        <translation>输入“%1”</translation>
    </message>
    <message>
        <source>handwheel %1 detents</source>
        <translation>手轮 %1 格</translation>
    </message>
    <message>
        <source>page %1</source>
        <translation>页面 %1</translation>
    </message>
    <message>
        <source>fault IN%1 %2</source>
        <translation>故障 IN%1 %2</translation>
    </message>
    <message>
        <source>language %1</source>
        <translation>语言 %1</translation>
    </message>
    <message>
        <source>load %1</source>
        <translation>载入 %1</translation>
    </message>
    <message>
        <source>time passes</source>
        <translation>等待</translation>
    </message>
    <message>
        <source>Pause (Space)</source>
        <translation>暂停（空格）</translation>
    </message>
    <message>
        <source>Play (Space)</source>
        <translation>播放（空格）</translation>
    </message>
    <message>
        <source>Block (.)</source>
        <translation>单段（.）</translation>
    </message>
    <message>
        <source>%1 (F8)</source>
        <translation>%1（F8）</translation>
    </message>
</context>
<context>
    <name>m350::ui::ReviewWindow</name>
    <message>
        <source>no folder for the attempt's machine: %1</source>
        <translation>无法为本次练习建立机床文件夹：%1</translation>
    </message>
    <message>
        <source>Follow the run</source>
        <translation>跟随运行</translation>
    </message>
    <message>
        <source>Machine view</source>
        <translation>图形显示</translation>
    </message>
    <message>
        <source>Panel</source>
        <translation>面板</translation>
    </message>
    <message>
        <source>(no name)</source>
        <translation>（无名）</translation>
    </message>
    <message>
        <source>Review: %1 · %2</source>
        <translation>回看：%1 · %2</translation>
    </message>
    <message>
        <source>Handed in: passed</source>
        <translation>交卷：通过</translation>
    </message>
    <message>
        <source>Handed in: failed (%1)</source>
        <translation>交卷：未通过（%1）</translation>
    </message>
</context>
<context>
    <name>m350::ui::RunningProgramView</name>
    <message>
        <source>No program has run yet</source>
        <translation>还没有程序运行</translation>
    </message>
    <message>
        <source>%1: cannot be read</source>
        <translation>%1: 无法读取</translation>
    </message>
    <message>
        <source>%1   Line %2</source>
        <translation>%1   行 %2</translation>
    </message>
    <message>
        <source>%1   (not running)</source>
        <translation>%1   （未运行）</translation>
    </message>
</context>
<context>
    <name>m350::ui::SessionWorker</name>
    <message>
        <source>No program loaded: load one on the Program page</source>
        <translation>未载入程序: 请在文件管理页面载入</translation>
    </message>
    <message>
        <source>A program is running: wait for it, or PAUSE / RESET first</source>
        <translation>程序正在运行: 请等待, 或先按暂停/复位</translation>
    </message>
    <message>
        <source>Set target tool No.:</source>
        <comment>msg 883</comment>
        <translation>设置目标刀具号:</translation>
    </message>
    <message>
        <source>Parameter %1: invalid value</source>
        <translation>[%1]号参数输入的数据非法!</translation>
    </message>
    <message>
        <source>Line %1 is not in the program</source>
        <translation>程序中没有第%1行</translation>
    </message>
    <message>
        <source>No paused run to resume (PAUSE, then RESET)</source>
        <translation>没有可恢复的暂停断点 (先暂停, 再复位)</translation>
    </message>
    <message>
        <source>No break point is kept in the machine folder</source>
        <translation>机床目录中没有保存的断点</translation>
    </message>
    <message>
        <source>External key %1</source>
        <translation>扩展按键%1</translation>
    </message>
    <message>
        <source>%1 stands for the panel key %2, which this panel does not press for it</source>
        <translation>%1 定义为面板按键 %2, 本面板不支持由它触发</translation>
    </message>
    <message>
        <source>IN%1: no such input (IN01-IN24)</source>
        <translation>IN%1: 无此输入口 (IN01-IN24)</translation>
    </message>
    <message>
        <source>File save failed!</source>
        <comment>msg 907</comment>
        <translation>文件生成失败!</translation>
    </message>
</context>
<context>
    <name>m350::ui::SimulationPanel</name>
    <message>
        <source>Max</source>
        <translation>最快</translation>
    </message>
    <message>
        <source>SL over</source>
        <comment>msg 125</comment>
        <translation>仿真结束</translation>
    </message>
    <message>
        <source>Start Simulating</source>
        <comment>msg 111</comment>
        <translation>开始仿真</translation>
    </message>
    <message>
        <source>%1  speed %2  line %3  %4 s  %5 blocks  %6 points</source>
        <translation>%1  速度 %2  行 %3  %4 秒  %5 段  %6 点</translation>
    </message>
</context>
<context>
    <name>m350::ui::SystemPage</name>
    <message>
        <source>System Info</source>
        <comment>msg 305</comment>
        <translation>系统管理</translation>
    </message>
    <message>
        <source>Registration</source>
        <comment>msg 536</comment>
        <translation>软件注册</translation>
    </message>
    <message>
        <source>The simulator needs no licence</source>
        <translation>模拟器无需注册</translation>
    </message>
    <message>
        <source>Password Set</source>
        <comment>msg 537</comment>
        <translation>密码设置</translation>
    </message>
    <message>
        <source>System Update</source>
        <comment>msg 538</comment>
        <translation>系统升级</translation>
    </message>
    <message>
        <source>A new version is a new build of M350 Studio</source>
        <translation>新版本即重新构建 M350 Studio</translation>
    </message>
    <message>
        <source>System Set</source>
        <comment>msg 539</comment>
        <translation>系统维护</translation>
    </message>
    <message>
        <source>Date, network and factory reset belong to the controller's system, which is not simulated</source>
        <translation>系统时间、网络与恢复出厂设置属于控制器系统, 未模拟</translation>
    </message>
    <message>
        <source>System BackUp</source>
        <comment>msg 540</comment>
        <translation>系统备份</translation>
    </message>
    <message>
        <source>Copy the machine folder to keep the whole machine</source>
        <translation>复制机床文件夹即可保存整台机床</translation>
    </message>
    <message>
        <source>User level</source>
        <translation>用户权限</translation>
    </message>
    <message>
        <source>System Name:</source>
        <comment>msg 930</comment>
        <translation>系统名称:</translation>
    </message>
    <message>
        <source>Software Ver:</source>
        <comment>msg 928</comment>
        <translation>系统软件版本:</translation>
    </message>
    <message>
        <source>Machine:</source>
        <translation>机床:</translation>
    </message>
    <message>
        <source>Machine folder:</source>
        <translation>机床文件夹:</translation>
    </message>
    <message>
        <source>Parameters:</source>
        <translation>参数:</translation>
    </message>
    <message>
        <source>Programs:</source>
        <translation>程序:</translation>
    </message>
    <message>
        <source>User level:</source>
        <translation>用户权限:</translation>
    </message>
    <message>
        <source>Passwords:</source>
        <translation>密码:</translation>
    </message>
    <message>
        <source>M350 Studio (a DDCS M350 panel simulator)</source>
        <translation>M350 Studio (DDCS M350 面板模拟器)</translation>
    </message>
    <message>
        <source>%1 catalogued, %2 on the Param page</source>
        <translation>共 %1 个, 参数页列出 %2 个</translation>
    </message>
    <message>
        <source>%1 .nc files in the machine folder</source>
        <translation>机床文件夹中 %1 个 .nc 文件</translation>
    </message>
    <message>
        <source>passwords.toml in order</source>
        <translation>passwords.toml 正常</translation>
    </message>
    <message>
        <source>Locked: passwords.toml cannot be trusted (%1), so only %2 opens and no default password comes back. Repair: set new passwords at the highest level, or run m350-sim reset-passwords --config FOLDER</source>
        <translation>已锁定: passwords.toml 不可信(%1), 只能以%2登录, 不会恢复默认密码。修复: 在最高权限下设置新密码, 或运行 m350-sim reset-passwords --config 机床文件夹</translation>
    </message>
</context>
<context>
    <name>m350::ui::ToolLifePage</name>
    <message>
        <source>Tool Life</source>
        <translation>刀具寿命</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>组号</translation>
    </message>
    <message>
        <source>Life type</source>
        <translation>寿命类型</translation>
    </message>
    <message>
        <source>Life</source>
        <translation>寿命</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>刀号</translation>
    </message>
    <message>
        <source>Used</source>
        <translation>已用</translation>
    </message>
    <message>
        <source>Remaining</source>
        <translation>剩余</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>UP/DOWN: tool (and its group). Reset Life: the group's tools start again from 0 used. Minutes count cutting feed only (no rapids, dwells, holds or tool changes), in whole 4 s units, shown as min:s. @ in use, # life reached.</source>
        <translation>上/下: 选择刀具(及其所在组)。寿命清零: 该组所有刀具的已用寿命归零。按分钟计的寿命只累计切削进给时间(快速移动、暂停、进给保持和换刀不计), 以4秒为单位, 显示为 分:秒。@ 使用中, # 寿命已到。</translation>
    </message>
    <message>
        <source>Reset Life</source>
        <translation>寿命清零</translation>
    </message>
    <message>
        <source>No tool life groups</source>
        <translation>没有刀具寿命组</translation>
    </message>
    <message>
        <source>Tool Table</source>
        <translation>刀具表</translation>
    </message>
    <message>
        <source>Simulator extra: the M350 itself has no tool life management. Here T%1+n selects group n (T%2 = group 1) and the T word changes the tool, as M06 does on FANUC.</source>
        <translation>模拟器扩展功能: M350本身没有刀具寿命管理。此处T%1+n选择第n组(T%2 = 第1组), T指令本身即换刀, 相当于FANUC的M06。</translation>
    </message>
    <message>
        <source>FANUC 0i: T%1 selects group 1 (the ignore number plus the group); M06 ends the counting of the old tool and starts it for the selected one.</source>
        <translation>FANUC 0i: T%1 选择第1组(忽略号加组号); M06 结束旧刀的寿命计数, 开始计数所选的新刀。</translation>
    </message>
    <message>
        <source>In use, life reached</source>
        <translation>使用中(寿命已到)</translation>
    </message>
    <message>
        <source>In use</source>
        <translation>使用中</translation>
    </message>
    <message>
        <source>Life reached</source>
        <translation>寿命已到</translation>
    </message>
    <message>
        <source>Selected, waits for the tool change</source>
        <translation>已选中,等待换刀</translation>
    </message>
    <message>
        <source>Waiting</source>
        <translation>待用</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>次数</translation>
    </message>
    <message>
        <source>Minutes</source>
        <translation>分钟</translation>
    </message>
    <message>
        <source>In use: group %1 T%2</source>
        <translation>使用中: 第%1组 T%2</translation>
    </message>
    <message>
        <source>In use: none</source>
        <translation>使用中: 无</translation>
    </message>
    <message>
        <source>Ignore No. %1</source>
        <translation>寿命管理忽略号 %1</translation>
    </message>
    <message>
        <source>Capacity: %1 groups x %2 tools</source>
        <translation>容量: %1组 x 每组%2把</translation>
    </message>
    <message>
        <source>No tool life groups. Enter them in a program or MDI: G10 L3, then P&lt;group&gt; L&lt;life&gt; Q&lt;1 count | 2 minutes&gt; and T&lt;tool&gt; H&lt;h&gt; D&lt;d&gt; blocks, then G11. They are kept in toollife.txt.</source>
        <translation>没有刀具寿命组。请在程序或MDI中输入: G10 L3, 然后 P&lt;组号&gt; L&lt;寿命&gt; Q&lt;1 次数 | 2 分钟&gt; 及 T&lt;刀号&gt; H&lt;h&gt; D&lt;d&gt; 程序段, 最后 G11。数据保存在 toollife.txt 中。</translation>
    </message>
    <message>
        <source>Every tool has reached its life in group %1: selecting it is an alarm.</source>
        <translation>第%1组所有刀具寿命已到: 选择该组将报警。</translation>
    </message>
    <message>
        <source>toollife.txt: %1 line(s) could not be read; they are kept in the file as comments.</source>
        <translation>toollife.txt: 有%1行无法读取, 已作为注释保留在文件中。</translation>
    </message>
    <message>
        <source>toollife.txt not saved: %1</source>
        <translation>toollife.txt 未保存: %1</translation>
    </message>
    <message>
        <source>Reset the tool life of group %1: every tool's used life back to 0?</source>
        <translation>第%1组刀具寿命清零: 所有刀具的已用寿命归零?</translation>
    </message>
</context>
<context>
    <name>m350::ui::ToolTablePage</name>
    <message>
        <source>Tool Table</source>
        <translation>刀具表</translation>
    </message>
    <message>
        <source>Flat end mill</source>
        <translation>平底铣刀</translation>
    </message>
    <message>
        <source>Ball nose</source>
        <translation>球头铣刀</translation>
    </message>
    <message>
        <source>Bull nose</source>
        <translation>圆鼻铣刀</translation>
    </message>
    <message>
        <source>Drill</source>
        <translation>钻头</translation>
    </message>
    <message>
        <source>Tap</source>
        <translation>丝锥</translation>
    </message>
    <message>
        <source>Chamfer</source>
        <translation>倒角刀</translation>
    </message>
    <message>
        <source>Engraver</source>
        <translation>雕刻刀</translation>
    </message>
    <message>
        <source>Face mill</source>
        <translation>面铣刀</translation>
    </message>
    <message>
        <source>Reamer</source>
        <translation>铰刀</translation>
    </message>
    <message>
        <source>Touch probe</source>
        <translation>测头</translation>
    </message>
    <message>
        <source>Other</source>
        <translation>其他</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>刀号</translation>
    </message>
    <message>
        <source>Pocket</source>
        <translation>刀位</translation>
    </message>
    <message>
        <source>Z offset</source>
        <translation>Z偏置</translation>
    </message>
    <message>
        <source>Diameter</source>
        <translation>直径</translation>
    </message>
    <message>
        <source>Max rpm</source>
        <translation>最高转速</translation>
    </message>
    <message>
        <source>Teeth</source>
        <translation>齿数</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>UP/DOWN: tool, LEFT/RIGHT: field, ENTER: edit. Touch Off: with the tool loaded and its tip on a known height, enter that work Z; the tool's Z offset changes so the display reads it.</source>
        <translation>上/下:选刀,左/右:选项,回车:修改。刀长设定:装上刀具,刀尖停在已知高度,输入该工件Z值;刀具Z偏置随之改变,使显示等于该值。</translation>
    </message>
    <message>
        <source>The table is the machine folder's tool.tbl in LinuxCNC's format; rpm, teeth and type are kept in the comment as {rpm=... teeth=... type=...}.</source>
        <translation>刀具表即机床文件夹中的tool.tbl(LinuxCNC格式);最高转速、齿数和类型保存在备注中:{rpm=... teeth=... type=...}。</translation>
    </message>
    <message>
        <source>Modify</source>
        <translation>修改</translation>
    </message>
    <message>
        <source>The table is empty</source>
        <translation>刀具表为空</translation>
    </message>
    <message>
        <source>New</source>
        <comment>msg 328</comment>
        <translation>新建</translation>
    </message>
    <message>
        <source>Del</source>
        <comment>msg 325</comment>
        <translation>删除</translation>
    </message>
    <message>
        <source>Touch Off</source>
        <translation>刀长设定</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>导入</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <source>Tool Life</source>
        <translation>刀具寿命</translation>
    </message>
    <message>
        <source>Breakage Monitor</source>
        <translation>破损监测</translation>
    </message>
    <message>
        <source>Cur Tool:</source>
        <comment>msg 992</comment>
        <translation>当前刀具号T:</translation>
    </message>
    <message>
        <source>%1 tools</source>
        <translation>共%1把刀</translation>
    </message>
    <message>
        <source>tool.tbl not saved: %1</source>
        <translation>tool.tbl未保存: %1</translation>
    </message>
    <message>
        <source>A tool keeps its number: add the new number with New and delete this one</source>
        <translation>刀号不能修改:用[新建]添加新刀号,再删除此刀</translation>
    </message>
    <message>
        <source>empty: none</source>
        <translation>留空:无</translation>
    </message>
    <message>
        <source>not a valid value</source>
        <translation>数值无效</translation>
    </message>
    <message>
        <source>T%1: %2</source>
        <translation>T%1: %2</translation>
    </message>
    <message>
        <source>New tool number:</source>
        <translation>新刀号:</translation>
    </message>
    <message>
        <source>Tool numbers start at 1</source>
        <translation>刀号从1开始</translation>
    </message>
    <message>
        <source>T%1 is already in the table</source>
        <translation>T%1已在刀具表中</translation>
    </message>
    <message>
        <source>The tool table is full (1000 tools)</source>
        <translation>刀具表已满(1000把刀)</translation>
    </message>
    <message>
        <source>Delete T%1 from the tool table?</source>
        <translation>从刀具表删除T%1?</translation>
    </message>
    <message>
        <source>The current tool No. is 0, this operation is invalid!</source>
        <comment>msg 858</comment>
        <translation>当前刀具号为0或非法,操作无效!</translation>
    </message>
    <message>
        <source>Touch off T%1: the work Z of its tip (gauge or cut surface):</source>
        <translation>T%1刀长设定:刀尖所在的工件Z值(量块或试切面):</translation>
    </message>
    <message>
        <source>Not a number: %1</source>
        <translation>不是数字: %1</translation>
    </message>
    <message>
        <source>Import a tool.tbl (path; relative to the machine folder):</source>
        <translation>导入tool.tbl(路径,相对于机床文件夹):</translation>
    </message>
    <message>
        <source>Replace the tool table with the %1 tools of %2?</source>
        <translation>用%2中的%1把刀替换刀具表?</translation>
    </message>
    <message>
        <source>%1 lines skipped, the first: %2</source>
        <translation>跳过%1行,第一行: %2</translation>
    </message>
    <message>
        <source>Tool table imported from %1</source>
        <translation>已从%1导入刀具表</translation>
    </message>
    <message>
        <source>Export the tool table to (path; relative to the machine folder):</source>
        <translation>导出刀具表到(路径,相对于机床文件夹):</translation>
    </message>
    <message>
        <source>%1 is the loaded program: refused, nothing was written</source>
        <translation>%1 是已加载的程序: 已拒绝, 未写入任何内容</translation>
    </message>
    <message>
        <source>File save failed!</source>
        <comment>msg 907</comment>
        <translation>文件生成失败!</translation>
    </message>
    <message>
        <source>Tool table exported to %1</source>
        <translation>刀具表已导出到%1</translation>
    </message>
</context>
<context>
    <name>m350::ui::TrainingStartPage</name>
    <message>
        <source>Training: %1</source>
        <translation>训练：%1</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>练习</translation>
    </message>
    <message>
        <source>Level</source>
        <translation>难度</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Best time</source>
        <translation>最佳用时</translation>
    </message>
    <message>
        <source>not tried</source>
        <translation>未练习</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>通过</translation>
    </message>
    <message>
        <source>failed (%1 tries)</source>
        <translation>未通过（已练 %1 次）</translation>
    </message>
</context>
<context>
    <name>m350::ui::TrainingWindow</name>
    <message>
        <source>The exam names exercise %1, which is not in %2</source>
        <translation>考试列出的练习 %1 不在 %2 中</translation>
    </message>
    <message>
        <source>Training</source>
        <translation>训练</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>打开</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>返回</translation>
    </message>
    <message>
        <source>Panel</source>
        <translation>面板</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <source>Task</source>
        <translation>任务</translation>
    </message>
    <message>
        <source>No hints (exam)</source>
        <translation>无提示（考试）</translation>
    </message>
    <message>
        <source>Hint</source>
        <translation>提示</translation>
    </message>
    <message>
        <source>Hand in</source>
        <translation>交卷</translation>
    </message>
    <message>
        <source>No more hints for this exercise.</source>
        <translation>本练习没有更多提示了。</translation>
    </message>
    <message>
        <source>Hint %1: %2</source>
        <translation>提示 %1：%2</translation>
    </message>
</context>
<context>
    <name>m350::ui::UserAccess</name>
    <message>
        <source>Guest</source>
        <comment>msg 942</comment>
        <translation>访客</translation>
    </message>
    <message>
        <source>Operator</source>
        <comment>msg 943</comment>
        <translation>操作员</translation>
    </message>
    <message>
        <source>Admin</source>
        <comment>msg 944</comment>
        <translation>管理员</translation>
    </message>
    <message>
        <source>Super</source>
        <comment>msg 945</comment>
        <translation>超级管理</translation>
    </message>
    <message>
        <source>Rights is limited,pls shift user's rights:</source>
        <comment>msg 934</comment>
        <translation>权限不足!请输入密码切换用户权限:</translation>
    </message>
    <message>
        <source>The No. of characters &lt; 6,pls input again!</source>
        <comment>msg 918</comment>
        <translation>输入的字符个数小于6个,请重新输入!</translation>
    </message>
    <message>
        <source>File save failed!</source>
        <comment>msg 907</comment>
        <translation>文件生成失败!</translation>
    </message>
</context>
<context>
    <name>m350::ui::VerdictPage</name>
    <message>
        <source>PASSED: %1</source>
        <translation>通过：%1</translation>
    </message>
    <message>
        <source>FAILED: %1</source>
        <translation>未通过：%1</translation>
    </message>
    <message>
        <source>score %1/100, time %2, hints %3</source>
        <translation>得分 %1/100，用时 %2，提示 %3 次</translation>
    </message>
    <message>
        <source>time out</source>
        <translation>超时</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>检查项</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>实测</translation>
    </message>
    <message>
        <source>Expected</source>
        <translation>应为</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>通过</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>未通过</translation>
    </message>
    <message>
        <source>parameter %1</source>
        <translation>参数 %1</translation>
    </message>
    <message>
        <source>output OUT%1</source>
        <translation>输出 OUT%1</translation>
    </message>
    <message>
        <source>tool T%1</source>
        <translation>刀具 T%1</translation>
    </message>
    <message>
        <source>This check passed.</source>
        <translation>此项检查通过。</translation>
    </message>
    <message>
        <source>F5 opens %1 in the panel.</source>
        <translation>F5 在面板中打开 %1。</translation>
    </message>
</context>
<context>
    <name>m350::ui::AttemptFile</name>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1：无法读取：%2</translation>
    </message>
    <message>
        <source>a line after the hand-in: the attempt ended on the line before</source>
        <translation>交卷之后还有一行：练习记录应在上一行结束</translation>
    </message>
    <message>
        <source>the line's hash does not follow the chain: the attempt was changed after it was recorded (or belongs to another exercise or exam)</source>
        <translation>此行的校验值与前面的链不符：练习记录在录制后被改动过（或属于另一个练习或考试）</translation>
    </message>
    <message>
        <source>the line has no hash while the lines before it have: the attempt was changed after it was recorded</source>
        <translation>前面各行都有校验值而此行没有：练习记录在录制后被改动过</translation>
    </message>
    <message>
        <source>"attempt" names the exercise and the trainee on the first line only</source>
        <translation>"attempt" 只能在第一行写明练习和学员</translation>
    </message>
    <message>
        <source>the hand-in's t must be a time not before the last action's (%1)</source>
        <translation>交卷的 t 不能早于最后一个操作的时间（%1）</translation>
    </message>
</context>
<context>
    <name>m350::ui::AttemptGrader</name>
    <message>
        <source>--verdict %1 is the attempt it grades: refused, nothing written</source>
        <translation>--verdict %1 就是要评分的练习记录：拒绝，未写入任何内容</translation>
    </message>
    <message>
        <source>--verdict %1 lies in the exercise folder %2: refused, nothing written</source>
        <translation>--verdict %1 位于练习文件夹 %2 中：拒绝，未写入任何内容</translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1：无法读取：%2</translation>
    </message>
    <message>
        <source>%1: the attempt carries no hash chain: an exam takes only attempts the panel recorded in the exam</source>
        <translation>%1：练习记录没有校验链：考试只接受面板在考试中录制的练习记录</translation>
    </message>
    <message>
        <source>%1:1: the attempt is at exercise "%2", not "%3"</source>
        <translation>%1:1：该练习记录属于练习 "%2"，不是 "%3"</translation>
    </message>
</context>
<context>
    <name>m350::ui::ClassReport</name>
    <message>
        <source>%1: no exercise "%2" in %3</source>
        <translation>%1：%3 中没有练习 "%2"</translation>
    </message>
</context>
<context>
    <name>m350::ui::CustomKeysPage</name>
    <message>
        <source>FUNC K01</source>
        <comment>msg 150</comment>
        <translation>扩展按键01</translation>
    </message>
    <message>
        <source>FUNC K02</source>
        <comment>msg 151</comment>
        <translation>扩展按键02</translation>
    </message>
    <message>
        <source>FUNC K03</source>
        <comment>msg 152</comment>
        <translation>扩展按键03</translation>
    </message>
    <message>
        <source>FUNC K04</source>
        <comment>msg 153</comment>
        <translation>扩展按键04</translation>
    </message>
    <message>
        <source>FUNC K05</source>
        <comment>msg 154</comment>
        <translation>扩展按键05</translation>
    </message>
    <message>
        <source>FUNC K06</source>
        <comment>msg 155</comment>
        <translation>扩展按键06</translation>
    </message>
    <message>
        <source>FUNC K07</source>
        <comment>msg 156</comment>
        <translation>扩展按键07</translation>
    </message>
    <message>
        <source>FUNC K08</source>
        <comment>msg 157</comment>
        <translation>扩展按键08</translation>
    </message>
    <message>
        <source>FUNC K09</source>
        <comment>msg 158</comment>
        <translation>扩展按键09</translation>
    </message>
    <message>
        <source>FUNC K10</source>
        <comment>msg 159</comment>
        <translation>扩展按键10</translation>
    </message>
    <message>
        <source>FUNC K11</source>
        <comment>msg 160</comment>
        <translation>扩展按键11</translation>
    </message>
    <message>
        <source>FUNC K12</source>
        <comment>msg 161</comment>
        <translation>扩展按键12</translation>
    </message>
    <message>
        <source>FUNC K13</source>
        <comment>msg 162</comment>
        <translation>扩展按键13</translation>
    </message>
    <message>
        <source>FUNC K14</source>
        <comment>msg 163</comment>
        <translation>扩展按键14</translation>
    </message>
</context>
<context>
    <name>m350::ui::ExternalOutputFile</name>
    <message>
        <source>File save failed!</source>
        <comment>msg 907</comment>
        <translation>文件生成失败!</translation>
    </message>
</context>
<context>
    <name>m350::ui::KeyPad</name>
    <message>
        <source>Monitor</source>
        <comment>msg 300</comment>
        <translation>加工状态</translation>
    </message>
    <message>
        <source>Program</source>
        <comment>msg 301</comment>
        <translation>文件管理</translation>
    </message>
    <message>
        <source>Param</source>
        <comment>msg 302</comment>
        <translation>参数管理</translation>
    </message>
    <message>
        <source>IO</source>
        <comment>msg 303</comment>
        <translation>IO状态</translation>
    </message>
    <message>
        <source>Log</source>
        <translation>系统日志</translation>
    </message>
    <message>
        <source>System</source>
        <translation>系统管理</translation>
    </message>
    <message>
        <source>MDI</source>
        <translation>MDI</translation>
    </message>
    <message>
        <source>Probe</source>
        <comment>msg 313</comment>
        <translation>对刀</translation>
    </message>
    <message>
        <source>CONT
STEP MPG</source>
        <translation>连续
寸动 手轮</translation>
    </message>
    <message>
        <source>MPG RUN</source>
        <translation>手轮试切</translation>
    </message>
    <message>
        <source>Hi/Lo</source>
        <translation>高/低速</translation>
    </message>
    <message>
        <source>Step...</source>
        <translation>输入寸动</translation>
    </message>
    <message>
        <source>Ext START</source>
        <translation>外部启动</translation>
    </message>
    <message>
        <source>E-STOP</source>
        <translation>急停</translation>
    </message>
    <message>
        <source>START</source>
        <translation>启动</translation>
    </message>
    <message>
        <source>PAUSE</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>RESET</source>
        <translation>复位</translation>
    </message>
    <message>
        <source>FRO
100%</source>
        <translation>进给
100%</translation>
    </message>
    <message>
        <source>FRO
+10%</source>
        <translation>进给
+10%</translation>
    </message>
    <message>
        <source>FRO
-10%</source>
        <translation>进给
-10%</translation>
    </message>
    <message>
        <source>SRO
100%</source>
        <translation>主轴
100%</translation>
    </message>
    <message>
        <source>SRO
+10%</source>
        <translation>主轴
+10%</translation>
    </message>
    <message>
        <source>SRO
-10%</source>
        <translation>主轴
-10%</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>主轴</translation>
    </message>
</context>
<context>
    <name>m350::ui::OperatorAction</name>
    <message>
        <source>"t" (virtual time in seconds, &gt;= 0) is missing or not a number</source>
        <translation>缺少 "t"（虚拟时间，单位秒，&gt;= 0）或它不是数字</translation>
    </message>
    <message>
        <source>one action per line: found %1 besides "t"</source>
        <translation>每行只能有一个操作：除 "t" 外还有 %1 个</translation>
    </message>
    <message>
        <source>unknown key "%1"</source>
        <translation>未知的按键 "%1"</translation>
    </message>
    <message>
        <source>softkey must be 1-6 (F1-F6) or 7-12 (second row)</source>
        <translation>softkey 须为 1-6（F1-F6）或 7-12（第二排）</translation>
    </message>
    <message>
        <source>unknown page "%1" (one of: %2)</source>
        <translation>未知的页面 "%1"（可用：%2）</translation>
    </message>
    <message>
        <source>lang must be zh_CN or en</source>
        <translation>lang 须为 zh_CN 或 en</translation>
    </message>
    <message>
        <source>wheel axis must be X, Y, Z, A or B</source>
        <translation>手轮轴须为 X、Y、Z、A 或 B</translation>
    </message>
    <message>
        <source>wheel step must be 1, 10 or 100</source>
        <translation>手轮倍率须为 1、10 或 100</translation>
    </message>
    <message>
        <source>wheel seconds must be &gt;= 0</source>
        <translation>手轮转动时间须 &gt;= 0</translation>
    </message>
    <message>
        <source>force input must be 1-24 (IN01-IN24)</source>
        <translation>force 的输入口须为 1-24（IN01-IN24）</translation>
    </message>
    <message>
        <source>force fault must be stuck, slow, bouncing, pressed or none</source>
        <translation>force 的故障须为 stuck、slow、bouncing、pressed 或 none</translation>
    </message>
    <message>
        <source>force level must be 0 or 1</source>
        <translation>force 的电平须为 0 或 1</translation>
    </message>
    <message>
        <source>unknown action "%1" (one of: key, key_down, key_up, softkey, text, wheel, page, force, lang, load)</source>
        <translation>未知的操作 "%1"（可用：key、key_down、key_up、softkey、text、wheel、page、force、lang、load）</translation>
    </message>
</context>
<context>
    <name>m350::ui::Replay</name>
    <message>
        <source>a line holds one action, a JSON object {...}</source>
        <translation>每行一个操作，即一个 JSON 对象 {...}</translation>
    </message>
    <message>
        <source>'%1' closes nothing that is open</source>
        <translation>'%1' 没有可闭合的括号</translation>
    </message>
    <message>
        <source>text after the action's closing }: one action a line</source>
        <translation>操作的结束 } 之后还有文字：每行只能一个操作</translation>
    </message>
    <message>
        <source>unterminated string: the " opened here is not closed on this line</source>
        <translation>字符串未结束：此处的 " 在本行没有闭合</translation>
    </message>
    <message>
        <source>missing '%1' at the end of the line (the '%2' at column %3 is not closed)</source>
        <translation>行尾缺少 '%1'（第 %3 列的 '%2' 没有闭合）</translation>
    </message>
    <message>
        <source>expected {...}</source>
        <translation>应为 {...}</translation>
    </message>
    <message>
        <source>t = %1 s is beyond the longest replay, %2 s (24 h) of virtual time</source>
        <translation>t = %1 秒超出了回放的最长时间，即 %2 秒（24 小时）虚拟时间</translation>
    </message>
    <message>
        <source>t = %1 comes before the previous action's %2 (actions must be in time order)</source>
        <translation>t = %1 早于上一个操作的 %2（操作须按时间顺序排列）</translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1：无法读取：%2</translation>
    </message>
    <message>
        <source>%1:%2:%3: load "%4": a replay loads only a program the Program page shows on its disks (%5), links followed: refused</source>
        <translation>%1:%2:%3：load "%4"：回放只能载入文件管理页各磁盘（%5）上显示的程序（链接按其目标判断）：已拒绝</translation>
    </message>
</context>
</TS>