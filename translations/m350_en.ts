<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="en_US">
<context>
    <name>m350::ui::CompactDro</name>
    <message>
        <source>Mach</source>
        <comment>msg 34</comment>
        <translation>Mach</translation>
    </message>
    <message>
        <source>Abs</source>
        <comment>msg 35</comment>
        <translation>Abs</translation>
    </message>
</context>
<context>
    <name>m350::ui::IoPage</name>
    <message>
        <source>IO</source>
        <comment>msg 303</comment>
        <translation>IO</translation>
    </message>
    <message>
        <source>Stat</source>
        <comment>msg 493</comment>
        <translation>Stat</translation>
    </message>
    <message>
        <source>Port Name</source>
        <comment>msg 130</comment>
        <translation>Port Name</translation>
    </message>
    <message>
        <source>Enable</source>
        <comment>msg 131</comment>
        <translation>Enable</translation>
    </message>
    <message>
        <source>Pin No.</source>
        <comment>msg 132</comment>
        <translation>Pin No.</translation>
    </message>
    <message>
        <source>Polarity</source>
        <comment>msg 133</comment>
        <translation>Polarity</translation>
    </message>
    <message>
        <source>Inputs IN01-IN24</source>
        <translation>Inputs IN01-IN24</translation>
    </message>
    <message>
        <source>Outputs OUT01-OUT21</source>
        <translation>Outputs OUT01-OUT21</translation>
    </message>
    <message>
        <source>Simulator only: a fault a trainer puts on the selected input</source>
        <translation>Simulator only: a fault a trainer puts on the selected input</translation>
    </message>
    <message>
        <source>The IO test screens drive real hardware; the simulator has none</source>
        <translation>The IO test screens drive real hardware; the simulator has none</translation>
    </message>
    <message>
        <source>Out Open</source>
        <comment>msg 396</comment>
        <translation>Out Open</translation>
    </message>
    <message>
        <source>Out Close</source>
        <comment>msg 397</comment>
        <translation>Out Close</translation>
    </message>
    <message>
        <source>Change Polarity</source>
        <comment>msg 399</comment>
        <translation>Change Polarity</translation>
    </message>
    <message>
        <source>Test</source>
        <comment>msg 401</comment>
        <translation>Test</translation>
    </message>
    <message>
        <source>Sim: stuck 0</source>
        <translation>Sim: stuck 0</translation>
    </message>
    <message>
        <source>Sim: stuck 1</source>
        <translation>Sim: stuck 1</translation>
    </message>
    <message>
        <source>Sim: slow 2 s</source>
        <translation>Sim: slow 2 s</translation>
    </message>
    <message>
        <source>Sim: bouncing</source>
        <translation>Sim: bouncing</translation>
    </message>
    <message>
        <source>Sim: clear fault</source>
        <translation>Sim: clear fault</translation>
    </message>
    <message>
        <source>Select a port first (UP/DOWN)</source>
        <translation>Select a port first (UP/DOWN)</translation>
    </message>
    <message>
        <source>Select an output port first (UP/DOWN)</source>
        <translation>Select an output port first (UP/DOWN)</translation>
    </message>
    <message>
        <source>Select an input port first (UP/DOWN)</source>
        <translation>Select an input port first (UP/DOWN)</translation>
    </message>
    <message>
        <source>Yes</source>
        <translation>Yes</translation>
    </message>
    <message>
        <source>No</source>
        <translation>No</translation>
    </message>
    <message>
        <source>Sensor watchdog: %1 awaited at %2 for %3 s (%4:%5)</source>
        <translation>Sensor watchdog: %1 awaited at %2 for %3 s (%4:%5)</translation>
    </message>
    <message>
        <source>Sensor watchdog: %1</source>
        <translation>Sensor watchdog: %1</translation>
    </message>
</context>
<context>
    <name>m350::ui::KeyPad</name>
    <message>
        <source>Monitor</source>
        <comment>msg 300</comment>
        <translation>Monitor</translation>
    </message>
    <message>
        <source>Program</source>
        <comment>msg 301</comment>
        <translation>Program</translation>
    </message>
    <message>
        <source>Param</source>
        <comment>msg 302</comment>
        <translation>Param</translation>
    </message>
    <message>
        <source>IO</source>
        <comment>msg 303</comment>
        <translation>IO</translation>
    </message>
    <message>
        <source>Log</source>
        <translation>Log</translation>
    </message>
    <message>
        <source>System</source>
        <translation>System</translation>
    </message>
    <message>
        <source>MDI</source>
        <translation>MDI</translation>
    </message>
    <message>
        <source>Probe</source>
        <comment>msg 313</comment>
        <translation>Probe</translation>
    </message>
    <message>
        <source>CONT
STEP MPG</source>
        <translation>CONT
STEP MPG</translation>
    </message>
    <message>
        <source>MPG RUN</source>
        <translation>MPG RUN</translation>
    </message>
    <message>
        <source>Hi/Lo</source>
        <translation>Hi/Lo</translation>
    </message>
    <message>
        <source>Step...</source>
        <translation>Step...</translation>
    </message>
    <message>
        <source>Ext START</source>
        <translation>Ext START</translation>
    </message>
    <message>
        <source>E-STOP</source>
        <translation>E-STOP</translation>
    </message>
    <message>
        <source>START</source>
        <translation>START</translation>
    </message>
    <message>
        <source>PAUSE</source>
        <translation>PAUSE</translation>
    </message>
    <message>
        <source>RESET</source>
        <translation>RESET</translation>
    </message>
    <message>
        <source>FRO
100%</source>
        <translation>FRO
100%</translation>
    </message>
    <message>
        <source>FRO
+10%</source>
        <translation>FRO
+10%</translation>
    </message>
    <message>
        <source>FRO
-10%</source>
        <translation>FRO
-10%</translation>
    </message>
    <message>
        <source>SRO
100%</source>
        <translation>SRO
100%</translation>
    </message>
    <message>
        <source>SRO
+10%</source>
        <translation>SRO
+10%</translation>
    </message>
    <message>
        <source>SRO
-10%</source>
        <translation>SRO
-10%</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Spindle</translation>
    </message>
    <message>
        <source>This page comes with the panel's part 2</source>
        <translation>This page comes with the panel's part 2</translation>
    </message>
</context>
<context>
    <name>m350::ui::MainWindow</name>
    <message>
        <source>This page comes with the panel's part 2</source>
        <translation>This page comes with the panel's part 2</translation>
    </message>
    <message>
        <source>Input the step distance (mm):</source>
        <translation>Input the step distance (mm):</translation>
    </message>
    <message>
        <source>Step distance must be a number from 0.001 to 100</source>
        <translation>Step distance must be a number from 0.001 to 100</translation>
    </message>
    <message>
        <source>Pause</source>
        <comment>msg 114</comment>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Waiting for %1 = %2 for %3 s (%4:%5)</source>
        <translation>Waiting for %1 = %2 for %3 s (%4:%5)</translation>
    </message>
    <message>
        <source>Go to home?</source>
        <comment>msg 140</comment>
        <translation>Go to home?</translation>
    </message>
    <message>
        <source>Recording stopped</source>
        <translation>Recording stopped</translation>
    </message>
    <message>
        <source>Record operator actions</source>
        <translation>Record operator actions</translation>
    </message>
    <message>
        <source>M350 Studio</source>
        <translation>M350 Studio</translation>
    </message>
    <message>
        <source>Panel</source>
        <translation>Panel</translation>
    </message>
    <message>
        <source>Record operator actions...</source>
        <translation>Record operator actions...</translation>
    </message>
    <message>
        <source>MPG RUN: reverse wheel retraces the path</source>
        <translation>MPG RUN: reverse wheel retraces the path</translation>
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
        <translation>[Knob]Move the cursor,[Enter]Edit current line,[Execute]Execute current line.</translation>
    </message>
    <message>
        <source>Execute(1)</source>
        <comment>msg 372</comment>
        <translation>Execute(1)</translation>
    </message>
    <message>
        <source>Execute(2)</source>
        <comment>msg 373</comment>
        <translation>Execute(2)</translation>
    </message>
    <message>
        <source>Execute(3)</source>
        <comment>msg 374</comment>
        <translation>Execute(3)</translation>
    </message>
    <message>
        <source>Execute(4)</source>
        <comment>msg 375</comment>
        <translation>Execute(4)</translation>
    </message>
    <message>
        <source>Execute(5)</source>
        <comment>msg 376</comment>
        <translation>Execute(5)</translation>
    </message>
    <message>
        <source>Execute(6)</source>
        <comment>msg 377</comment>
        <translation>Execute(6)</translation>
    </message>
    <message>
        <source>MDI line %1 is empty</source>
        <translation>MDI line %1 is empty</translation>
    </message>
    <message>
        <source>Execute(%1)</source>
        <translation>Execute(%1)</translation>
    </message>
    <message>
        <source>BUSY</source>
        <comment>msg 21</comment>
        <translation>BUSY</translation>
    </message>
    <message>
        <source>done</source>
        <translation>done</translation>
    </message>
    <message>
        <source>ALARM</source>
        <comment>msg 24</comment>
        <translation>ALARM</translation>
    </message>
</context>
<context>
    <name>m350::ui::MonitorPage</name>
    <message>
        <source>Monitor</source>
        <comment>msg 300</comment>
        <translation>Monitor</translation>
    </message>
    <message>
        <source>Axis</source>
        <comment>msg 33</comment>
        <translation>Axis</translation>
    </message>
    <message>
        <source>Mach</source>
        <comment>msg 34</comment>
        <translation>Mach</translation>
    </message>
    <message>
        <source>Abs</source>
        <comment>msg 35</comment>
        <translation>Abs</translation>
    </message>
    <message>
        <source>Coord:</source>
        <comment>msg 991</comment>
        <translation>Coord:</translation>
    </message>
    <message>
        <source>FRO</source>
        <comment>msg 30</comment>
        <translation>FRO</translation>
    </message>
    <message>
        <source>SRO</source>
        <comment>msg 31</comment>
        <translation>SRO</translation>
    </message>
    <message>
        <source>SJR</source>
        <comment>msg 32</comment>
        <translation>SJR</translation>
    </message>
    <message>
        <source>Feed Rate</source>
        <comment>msg 36</comment>
        <translation>Feed Rate</translation>
    </message>
    <message>
        <source>Cur Tool</source>
        <comment>msg 46</comment>
        <translation>Cur Tool</translation>
    </message>
    <message>
        <source>Total No.</source>
        <comment>msg 47</comment>
        <translation>Total No.</translation>
    </message>
    <message>
        <source>Cur No.</source>
        <comment>msg 48</comment>
        <translation>Cur No.</translation>
    </message>
    <message>
        <source>Work Time</source>
        <comment>msg 49</comment>
        <translation>Work Time</translation>
    </message>
    <message>
        <source>INC Distance</source>
        <comment>msg 244</comment>
        <translation>INC Distance</translation>
    </message>
    <message>
        <source>Comes with the panel's part 2</source>
        <translation>Comes with the panel's part 2</translation>
    </message>
    <message>
        <source>X Go Home</source>
        <comment>msg 420</comment>
        <translation>X Go Home</translation>
    </message>
    <message>
        <source>Y Go Home</source>
        <comment>msg 421</comment>
        <translation>Y Go Home</translation>
    </message>
    <message>
        <source>Z Go Home</source>
        <comment>msg 422</comment>
        <translation>Z Go Home</translation>
    </message>
    <message>
        <source>4th Go Home</source>
        <comment>msg 423</comment>
        <translation>4th Go Home</translation>
    </message>
    <message>
        <source>5th Go Home</source>
        <comment>msg 424</comment>
        <translation>5th Go Home</translation>
    </message>
    <message>
        <source>All Go Home</source>
        <comment>msg 425</comment>
        <translation>All Go Home</translation>
    </message>
    <message>
        <source>X Go Zero</source>
        <comment>msg 432</comment>
        <translation>X Go Zero</translation>
    </message>
    <message>
        <source>Y Go Zero</source>
        <comment>msg 433</comment>
        <translation>Y Go Zero</translation>
    </message>
    <message>
        <source>Z Go Zero</source>
        <comment>msg 434</comment>
        <translation>Z Go Zero</translation>
    </message>
    <message>
        <source>4th Go Zero</source>
        <comment>msg 435</comment>
        <translation>4th Go Zero</translation>
    </message>
    <message>
        <source>5th Go Zero</source>
        <comment>msg 436</comment>
        <translation>5th Go Zero</translation>
    </message>
    <message>
        <source>All Go Zero</source>
        <comment>msg 437</comment>
        <translation>All Go Zero</translation>
    </message>
    <message>
        <source>Clear X</source>
        <comment>msg 444</comment>
        <translation>Clear X</translation>
    </message>
    <message>
        <source>Clear Y</source>
        <comment>msg 445</comment>
        <translation>Clear Y</translation>
    </message>
    <message>
        <source>Clear Z</source>
        <comment>msg 446</comment>
        <translation>Clear Z</translation>
    </message>
    <message>
        <source>Clear 4th</source>
        <comment>msg 447</comment>
        <translation>Clear 4th</translation>
    </message>
    <message>
        <source>Clear 5th</source>
        <comment>msg 448</comment>
        <translation>Clear 5th</translation>
    </message>
    <message>
        <source>Clear All</source>
        <comment>msg 449</comment>
        <translation>Clear All</translation>
    </message>
    <message>
        <source>Simulation</source>
        <comment>msg 312</comment>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>Probe</source>
        <comment>msg 313</comment>
        <translation>Probe</translation>
    </message>
    <message>
        <source>Go Work Zero</source>
        <comment>msg 314</comment>
        <translation>Go Work Zero</translation>
    </message>
    <message>
        <source>Go Home</source>
        <comment>msg 315</comment>
        <translation>Go Home</translation>
    </message>
    <message>
        <source>Clear</source>
        <comment>msg 316</comment>
        <translation>Clear</translation>
    </message>
    <message>
        <source>Break Run</source>
        <comment>msg 317</comment>
        <translation>Break Run</translation>
    </message>
    <message>
        <source>Manual</source>
        <comment>msg 318</comment>
        <translation>Manual</translation>
    </message>
    <message>
        <source>Coord Set</source>
        <comment>msg 319</comment>
        <translation>Coord Set</translation>
    </message>
    <message>
        <source>MDI</source>
        <comment>msg 320</comment>
        <translation>MDI</translation>
    </message>
    <message>
        <source>Middle</source>
        <comment>msg 321</comment>
        <translation>Middle</translation>
    </message>
    <message>
        <source>Work Record</source>
        <comment>msg 322</comment>
        <translation>Work Record</translation>
    </message>
    <message>
        <source>Sort Proces</source>
        <comment>msg 323</comment>
        <translation>Sort Proces</translation>
    </message>
    <message>
        <source>Homed</source>
        <translation>Homed</translation>
    </message>
    <message>
        <source>Not homed</source>
        <translation>Not homed</translation>
    </message>
    <message>
        <source>Servo S</source>
        <comment>msg 38</comment>
        <translation>Servo S</translation>
    </message>
    <message>
        <source>Mult S</source>
        <comment>msg 39</comment>
        <translation>Mult S</translation>
    </message>
    <message>
        <source>Analog S</source>
        <comment>msg 37</comment>
        <translation>Analog S</translation>
    </message>
    <message>
        <source>High</source>
        <comment>msg 873</comment>
        <translation>High</translation>
    </message>
    <message>
        <source>Low</source>
        <comment>msg 872</comment>
        <translation>Low</translation>
    </message>
</context>
<context>
    <name>m350::ui::PanelText</name>
    <message>
        <source>CONT</source>
        <comment>msg 0</comment>
        <translation>CONT</translation>
    </message>
    <message>
        <source>STEP</source>
        <comment>msg 1</comment>
        <translation>STEP</translation>
    </message>
    <message>
        <source>MPG</source>
        <comment>msg 2</comment>
        <translation>MPG</translation>
    </message>
    <message>
        <source>ZERO</source>
        <comment>msg 3</comment>
        <translation>ZERO</translation>
    </message>
    <message>
        <source>GOTOZ</source>
        <comment>msg 4</comment>
        <translation>GOTOZ</translation>
    </message>
    <message>
        <source>HOME</source>
        <comment>msg 5</comment>
        <translation>HOME</translation>
    </message>
    <message>
        <source>PROBE</source>
        <comment>msg 6</comment>
        <translation>PROBE</translation>
    </message>
    <message>
        <source>MIDDLE</source>
        <comment>msg 7</comment>
        <translation>MIDDLE</translation>
    </message>
    <message>
        <source>AUTO</source>
        <comment>msg 8</comment>
        <translation>AUTO</translation>
    </message>
    <message>
        <source>SL</source>
        <comment>msg 9</comment>
        <translation>SL</translation>
    </message>
    <message>
        <source>WHEEL</source>
        <comment>msg 10</comment>
        <translation>WHEEL</translation>
    </message>
    <message>
        <source>MDI</source>
        <comment>msg 11</comment>
        <translation>MDI</translation>
    </message>
    <message>
        <source>READY</source>
        <comment>msg 20</comment>
        <translation>READY</translation>
    </message>
    <message>
        <source>BUSY</source>
        <comment>msg 21</comment>
        <translation>BUSY</translation>
    </message>
    <message>
        <source>RESET</source>
        <comment>msg 22</comment>
        <translation>RESET</translation>
    </message>
    <message>
        <source>ERROR</source>
        <comment>msg 23</comment>
        <translation>ERROR</translation>
    </message>
    <message>
        <source>ALARM</source>
        <comment>msg 24</comment>
        <translation>ALARM</translation>
    </message>
    <message>
        <source>WHEEL</source>
        <comment>msg 25</comment>
        <translation>WHEEL</translation>
    </message>
    <message>
        <source>WHEEL REV</source>
        <comment>msg 26</comment>
        <translation>WHEEL REV</translation>
    </message>
    <message>
        <source>STOP</source>
        <comment>msg 40</comment>
        <translation>STOP</translation>
    </message>
    <message>
        <source>FWD</source>
        <comment>msg 41</comment>
        <translation>FWD</translation>
    </message>
    <message>
        <source>REV</source>
        <comment>msg 42</comment>
        <translation>REV</translation>
    </message>
    <message>
        <source>JOG</source>
        <comment>msg 43</comment>
        <translation>JOG</translation>
    </message>
    <message>
        <source>TAP</source>
        <comment>msg 44</comment>
        <translation>TAP</translation>
    </message>
    <message>
        <source>PRCE STOP</source>
        <comment>msg 45</comment>
        <translation>PRCE STOP</translation>
    </message>
</context>
<context>
    <name>m350::ui::ProbePage</name>
    <message>
        <source>Probe</source>
        <comment>msg 6</comment>
        <translation>Probe</translation>
    </message>
    <message>
        <source>Coord:</source>
        <comment>msg 991</comment>
        <translation>Coord:</translation>
    </message>
    <message>
        <source>Cur Tool:</source>
        <comment>msg 992</comment>
        <translation>Cur Tool:</translation>
    </message>
    <message>
        <source>THK Of Probe:</source>
        <comment>msg 993</comment>
        <translation>THK Of Probe:</translation>
    </message>
    <message>
        <source>Fixed Probe X:</source>
        <comment>msg 994</comment>
        <translation>Fixed Probe X:</translation>
    </message>
    <message>
        <source>Fixed Probe Y:</source>
        <comment>msg 995</comment>
        <translation>Fixed Probe Y:</translation>
    </message>
    <message>
        <source>Fixed Probe Z:</source>
        <comment>msg 996</comment>
        <translation>Fixed Probe Z:</translation>
    </message>
    <message>
        <source>Tool Z offsets (params 930-945)</source>
        <translation>Tool Z offsets (params 930-945)</translation>
    </message>
    <message>
        <source>Multi-tool selection:</source>
        <comment>msg 864</comment>
        <translation>Multi-tool selection:</translation>
    </message>
    <message>
        <source>1:Before operate [Floating Probe],Pls move tool above the block and set Param 129;</source>
        <comment>msg 984</comment>
        <translation>1:Before operate [Floating Probe],Pls move tool above the block and set Param 129;</translation>
    </message>
    <message>
        <source>2:[Fixed Probe]Input the cutter No.,record the offset of Z axis after tool change;</source>
        <comment>msg 985</comment>
        <translation>2:[Fixed Probe]Input the cutter No.,record the offset of Z axis after tool change;</translation>
    </message>
    <message>
        <source>3:[Mult Probe] Probe several tools at one time.select the Tools and press [Mult Probe];</source>
        <comment>msg 986</comment>
        <translation>3:[Mult Probe] Probe several tools at one time.select the Tools and press [Mult Probe];</translation>
    </message>
    <message>
        <source>Floating Probe</source>
        <comment>msg 468</comment>
        <translation>Floating Probe</translation>
    </message>
    <message>
        <source>Fixed Probe</source>
        <comment>msg 470</comment>
        <translation>Fixed Probe</translation>
    </message>
    <message>
        <source>Mult Probe</source>
        <comment>msg 471</comment>
        <translation>Mult Probe</translation>
    </message>
    <message>
        <source>XY Teach</source>
        <comment>msg 472</comment>
        <translation>XY Teach</translation>
    </message>
    <message>
        <source>Z Teach</source>
        <comment>msg 473</comment>
        <translation>Z Teach</translation>
    </message>
    <message>
        <source>Tool is above the probe sensor?</source>
        <comment>msg 982</comment>
        <translation>Tool is above the probe sensor?</translation>
    </message>
    <message>
        <source>Enter the tool number:</source>
        <comment>msg 863</comment>
        <translation>Enter the tool number:</translation>
    </message>
    <message>
        <source>The current tool No. is 0, this operation is invalid!</source>
        <comment>msg 858</comment>
        <translation>The current tool No. is 0, this operation is invalid!</translation>
    </message>
    <message>
        <source>Exceeded the maximum!</source>
        <comment>msg 884</comment>
        <translation>Exceeded the maximum!</translation>
    </message>
    <message>
        <source>Is the workpiece zero set for the Z axis?</source>
        <comment>msg 983</comment>
        <translation>Is the workpiece zero set for the Z axis?</translation>
    </message>
    <message>
        <source>Pls determine the Z-axis workpiece zero!</source>
        <comment>msg 869</comment>
        <translation>Pls determine the Z-axis workpiece zero!</translation>
    </message>
    <message>
        <source>Select the tools first (arrows move, Enter selects)</source>
        <translation>Select the tools first (arrows move, Enter selects)</translation>
    </message>
    <message>
        <source>One Key probe for the selected tool?</source>
        <comment>msg 866</comment>
        <translation>One Key probe for the selected tool?</translation>
    </message>
    <message>
        <source>(XY)Mach pos is XY pos of Probe?</source>
        <comment>msg 148</comment>
        <translation>(XY)Mach pos is XY pos of Probe?</translation>
    </message>
    <message>
        <source>(Z)Mach pos is Z pos of Probe?</source>
        <comment>msg 149</comment>
        <translation>(Z)Mach pos is Z pos of Probe?</translation>
    </message>
    <message>
        <source>Probing: %1:%2</source>
        <translation>Probing: %1:%2</translation>
    </message>
</context>
<context>
    <name>m350::ui::PromptBox</name>
    <message>
        <source>[Enter] OK    [Esc] Cancel</source>
        <translation>[Enter] OK    [Esc] Cancel</translation>
    </message>
</context>
<context>
    <name>m350::ui::SessionWorker</name>
    <message>
        <source>No program loaded: open one with m350-hmi FILE (the Program page comes with part 2)</source>
        <translation>No program loaded: open one with m350-hmi FILE (the Program page comes with part 2)</translation>
    </message>
    <message>
        <source>A program is running: wait for it, or PAUSE / RESET first</source>
        <translation>A program is running: wait for it, or PAUSE / RESET first</translation>
    </message>
    <message>
        <source>Parameter %1: invalid value</source>
        <translation>Parameter %1: invalid value</translation>
    </message>
    <message>
        <source>IN%1: no such input (IN01-IN24)</source>
        <translation>IN%1: no such input (IN01-IN24)</translation>
    </message>
</context>
</TS>