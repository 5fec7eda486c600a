<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="zh_CN">
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
        <source>Select a port first (UP/DOWN)</source>
        <translation>请先选择端口(上/下键)</translation>
    </message>
    <message>
        <source>Select an output port first (UP/DOWN)</source>
        <translation>请先选择输出端口(上/下键)</translation>
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
    <message>
        <source>This page comes with the panel's part 2</source>
        <translation>该页面将在面板第二部分提供</translation>
    </message>
</context>
<context>
    <name>m350::ui::MainWindow</name>
    <message>
        <source>This page comes with the panel's part 2</source>
        <translation>该页面将在面板第二部分提供</translation>
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
        <source>Recording stopped</source>
        <translation>操作录制已停止</translation>
    </message>
    <message>
        <source>Record operator actions</source>
        <translation>录制操作</translation>
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
        <source>Comes with the panel's part 2</source>
        <translation>将在面板第二部分提供</translation>
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
    <name>m350::ui::PromptBox</name>
    <message>
        <source>[Enter] OK    [Esc] Cancel</source>
        <translation>[确认]确定    [取消]退出</translation>
    </message>
</context>
<context>
    <name>m350::ui::SessionWorker</name>
    <message>
        <source>No program loaded: open one with m350-hmi FILE (the Program page comes with part 2)</source>
        <translation>未载入加工文件: 用 m350-hmi 文件名 打开 (文件管理页面将在第二部分提供)</translation>
    </message>
    <message>
        <source>A program is running: wait for it, or PAUSE / RESET first</source>
        <translation>程序正在运行: 请等待, 或先按暂停/复位</translation>
    </message>
    <message>
        <source>Parameter %1: invalid value</source>
        <translation>[%1]号参数输入的数据非法!</translation>
    </message>
    <message>
        <source>IN%1: no such input (IN01-IN24)</source>
        <translation>IN%1: 无此输入口 (IN01-IN24)</translation>
    </message>
</context>
</TS>