<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="en_US">
<context>
    <name>m350::ui::ActionRecorder</name>
    <message>
        <source>%1: cannot write: %2</source>
        <translation>%1: cannot write: %2</translation>
    </message>
    <message>
        <source>it is a folder</source>
        <translation>it is a folder</translation>
    </message>
</context>
<context>
    <name>m350::ui::AttemptRun</name>
    <message>
        <source>no folder for the attempt's machine: %1</source>
        <translation>no folder for the attempt's machine: %1</translation>
    </message>
    <message>
        <source>Training: %1 · time left %2:%3 · F7: task, hint, hand in</source>
        <translation>Training: %1 · time left %2:%3 · F7: task, hint, hand in</translation>
    </message>
</context>
<context>
    <name>m350::ui::BackupImportFlow</name>
    <message>
        <source>Controller backup: the folder that holds setting, slib-g.nc ...</source>
        <translation>Controller backup: the folder that holds setting, slib-g.nc ...</translation>
    </message>
    <message>
        <source>New machine folder (a new or empty folder)</source>
        <translation>New machine folder (a new or empty folder)</translation>
    </message>
    <message>
        <source>An import is under way: wait for its report</source>
        <translation>An import is under way: wait for its report</translation>
    </message>
    <message>
        <source>Importing %1 ...</source>
        <translation>Importing %1 ...</translation>
    </message>
    <message>
        <source>Import refused:
%1: %2</source>
        <translation>Import refused:
%1: %2</translation>
    </message>
    <message>
        <source>%1 already holds this backup's import; nothing written</source>
        <translation>%1 already holds this backup's import; nothing written</translation>
    </message>
    <message>
        <source>Machine folder made from the backup:
%1</source>
        <translation>Machine folder made from the backup:
%1</translation>
    </message>
    <message>
        <source>%1 parameters, %2 differ from the factory values</source>
        <translation>%1 parameters, %2 differ from the factory values</translation>
    </message>
    <message>
        <source>.nc files copied as they were: %1; other files not copied: %2</source>
        <translation>.nc files copied as they were: %1; other files not copied: %2</translation>
    </message>
    <message>
        <source>%1 stated values to review in machine.toml</source>
        <translation>%1 stated values to review in machine.toml</translation>
    </message>
    <message>
        <source>The simulator cannot model:</source>
        <translation>The simulator cannot model:</translation>
    </message>
    <message>
        <source>%1 syntax errors the simulator does not accept yet</source>
        <translation>%1 syntax errors the simulator does not accept yet</translation>
    </message>
    <message>
        <source>The whole report: %1</source>
        <translation>The whole report: %1</translation>
    </message>
    <message>
        <source>Open it with: m350-hmi --config %1</source>
        <translation>Open it with: m350-hmi --config %1</translation>
    </message>
    <message>
        <source>Switch the panel to this machine now?</source>
        <translation>Switch the panel to this machine now?</translation>
    </message>
</context>
<context>
    <name>m350::ui::BreakRunPage</name>
    <message>
        <source>Break Run</source>
        <comment>msg 317</comment>
        <translation>Break Run</translation>
    </message>
    <message>
        <source>Start Line</source>
        <comment>msg 456</comment>
        <translation>Start Line</translation>
    </message>
    <message>
        <source>Power Resume</source>
        <comment>msg 457</comment>
        <translation>Power Resume</translation>
    </message>
    <message>
        <source>Pause Resume</source>
        <comment>msg 458</comment>
        <translation>Pause Resume</translation>
    </message>
    <message>
        <source>Breakpoint find out, do you want to start ?/[%s]</source>
        <comment>msg 860</comment>
        <translation>Breakpoint find out, do you want to start ?/[%s]</translation>
    </message>
    <message>
        <source>No program loaded: load one on the Program page</source>
        <translation>No program loaded: load one on the Program page</translation>
    </message>
    <message>
        <source>Start line no.:</source>
        <comment>msg 94</comment>
        <translation>Start line no.:</translation>
    </message>
    <message>
        <source>Line %1 is not in the program</source>
        <translation>Line %1 is not in the program</translation>
    </message>
    <message>
        <source>No break point is kept in the machine folder</source>
        <translation>No break point is kept in the machine folder</translation>
    </message>
    <message>
        <source>No paused run to resume (PAUSE, then RESET)</source>
        <translation>No paused run to resume (PAUSE, then RESET)</translation>
    </message>
    <message>
        <source>BreakPoint%d:%s L:%d</source>
        <comment>msg 102</comment>
        <translation>BreakPoint%d:%s L:%d</translation>
    </message>
    <message>
        <source>Current file:</source>
        <comment>msg 876</comment>
        <translation>Current file:</translation>
    </message>
</context>
<context>
    <name>m350::ui::BreakageMonitorPage</name>
    <message>
        <source>Breakage Monitor</source>
        <translation>Breakage Monitor</translation>
    </message>
    <message>
        <source>Tool Table</source>
        <translation>Tool Table</translation>
    </message>
    <message>
        <source>Current tool:</source>
        <translation>Current tool:</translation>
    </message>
    <message>
        <source>Spindle load:</source>
        <translation>Spindle load:</translation>
    </message>
    <message>
        <source>Register:</source>
        <translation>Register:</translation>
    </message>
    <message>
        <source>Lambda (param 4127):</source>
        <translation>Lambda (param 4127):</translation>
    </message>
    <message>
        <source>Limits:</source>
        <translation>Limits:</translation>
    </message>
    <message>
        <source>Rule:</source>
        <translation>Rule:</translation>
    </message>
    <message>
        <source>Alarm:</source>
        <translation>Alarm:</translation>
    </message>
    <message>
        <source>Load %</source>
        <translation>Load %</translation>
    </message>
    <message>
        <source>Lower limit</source>
        <translation>Lower limit</translation>
    </message>
    <message>
        <source>Upper limit</source>
        <translation>Upper limit</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Time (s)</translation>
    </message>
    <message>
        <source>Load (%)</source>
        <translation>Load (%)</translation>
    </message>
    <message>
        <source>Load% = L / 32767 x lambda, kept x100 in a 16-bit register. Limits per tool in spindle-load.toml; the lower one counts only while the tool cuts.</source>
        <translation>Load% = L / 32767 x lambda, kept x100 in a 16-bit register. Limits per tool in spindle-load.toml; the lower one counts only while the tool cuts.</translation>
    </message>
    <message>
        <source>None</source>
        <translation>None</translation>
    </message>
    <message>
        <source>This machine has no spindle load model ([spindle_load] in machine.toml).</source>
        <translation>This machine has no spindle load model ([spindle_load] in machine.toml).</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>none for this tool</source>
        <translation>none for this tool</translation>
    </message>
    <message>
        <source>%1 samples in a row out of the limits, one every %2 ms</source>
        <translation>%1 samples in a row out of the limits, one every %2 ms</translation>
    </message>
</context>
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
    <name>m350::ui::CoordPage</name>
    <message>
        <source>Coord Set</source>
        <comment>msg 319</comment>
        <translation>Coord Set</translation>
    </message>
    <message>
        <source>Offset</source>
        <comment>msg 87</comment>
        <translation>Offset</translation>
    </message>
    <message>
        <source>G92</source>
        <comment>msg 232</comment>
        <translation>G92</translation>
    </message>
    <message>
        <source>1:[Knob]Move the cursor,[Enter]modify.</source>
        <comment>msg 997</comment>
        <translation>1:[Knob]Move the cursor,[Enter]modify.</translation>
    </message>
    <message>
        <source>2:[Deeper] and [Move Up]Modified Z ext-offset.</source>
        <comment>msg 998</comment>
        <translation>2:[Deeper] and [Move Up]Modified Z ext-offset.</translation>
    </message>
    <message>
        <source>Clear 4th</source>
        <comment>msg 507</comment>
        <translation>Clear 4th</translation>
    </message>
    <message>
        <source>Clear 5th</source>
        <comment>msg 508</comment>
        <translation>Clear 5th</translation>
    </message>
    <message>
        <source>Select Coord</source>
        <comment>msg 500</comment>
        <translation>Select Coord</translation>
    </message>
    <message>
        <source>Clear X</source>
        <comment>msg 501</comment>
        <translation>Clear X</translation>
    </message>
    <message>
        <source>Clear Y</source>
        <comment>msg 502</comment>
        <translation>Clear Y</translation>
    </message>
    <message>
        <source>Clear Z</source>
        <comment>msg 503</comment>
        <translation>Clear Z</translation>
    </message>
    <message>
        <source>Z Step</source>
        <comment>msg 504</comment>
        <translation>Z Step</translation>
    </message>
    <message>
        <source>Deeper</source>
        <comment>msg 505</comment>
        <translation>Deeper</translation>
    </message>
    <message>
        <source>Move up</source>
        <comment>msg 506</comment>
        <translation>Move up</translation>
    </message>
    <message>
        <source>Select the work system: 0 = G92, 1-6 = G54-G59</source>
        <translation>Select the work system: 0 = G92, 1-6 = G54-G59</translation>
    </message>
    <message>
        <source>Is not G54-G59 coordinate!</source>
        <comment>msg 987</comment>
        <translation>Is not G54-G59 coordinate!</translation>
    </message>
    <message>
        <source>Z Step:</source>
        <comment>msg 999</comment>
        <translation>Z Step:</translation>
    </message>
    <message>
        <source>Step distance must be a number from 0.001 to 100</source>
        <translation>Step distance must be a number from 0.001 to 100</translation>
    </message>
    <message>
        <source>Axis Abs pos:</source>
        <comment>msg 93</comment>
        <translation>Axis Abs pos:</translation>
    </message>
    <message>
        <source>Not a number: %1</source>
        <translation>Not a number: %1</translation>
    </message>
</context>
<context>
    <name>m350::ui::CustomKeysPage</name>
    <message>
        <source>Manual</source>
        <comment>msg 318</comment>
        <translation>Manual</translation>
    </message>
    <message>
        <source>%1 runs M#1996 (#1996 = M250-M263 for K01-K14). UP/DOWN/LEFT/RIGHT: key, ENTER: press.</source>
        <translation>%1 runs M#1996 (#1996 = M250-M263 for K01-K14). UP/DOWN/LEFT/RIGHT: key, ENTER: press.</translation>
    </message>
    <message>
        <source>No %1 in the machine folder: a key runs its M code (M250-M263) as MDI. UP/DOWN/LEFT/RIGHT: key, ENTER: press.</source>
        <translation>No %1 in the machine folder: a key runs its M code (M250-M263) as MDI. UP/DOWN/LEFT/RIGHT: key, ENTER: press.</translation>
    </message>
    <message>
        <source>Manual</source>
        <comment>msg 480</comment>
        <translation>Manual</translation>
    </message>
    <message>
        <source>Presses the selected FUNC key</source>
        <translation>Presses the selected FUNC key</translation>
    </message>
    <message>
        <source>CAM</source>
        <comment>msg 482</comment>
        <translation>CAM</translation>
    </message>
    <message>
        <source>The CAM wizard pages (CAM.nc) are not simulated</source>
        <translation>The CAM wizard pages (CAM.nc) are not simulated</translation>
    </message>
</context>
<context>
    <name>m350::ui::GraphicsPage</name>
    <message>
        <source>Simulation</source>
        <comment>msg 312</comment>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>Top View</source>
        <translation>Top View</translation>
    </message>
    <message>
        <source>Front View</source>
        <translation>Front View</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Fit</translation>
    </message>
    <message>
        <source>Zoom In</source>
        <translation>Zoom In</translation>
    </message>
    <message>
        <source>Zoom Out</source>
        <translation>Zoom Out</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Back</translation>
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
        <source>Sim: press</source>
        <translation>Sim: press</translation>
    </message>
    <message>
        <source>Simulator only: the selected input reads its active level for 0.3 s, as a key pressed</source>
        <translation>Simulator only: the selected input reads its active level for 0.3 s, as a key pressed</translation>
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
        <source>T%1 is in the spindle: releasing the drawbar drops it. Release it?</source>
        <translation>T%1 is in the spindle: releasing the drawbar drops it. Release it?</translation>
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
    <name>m350::ui::LevelPrompt</name>
    <message>
        <source>Pls input super admi or hight user's rights:</source>
        <comment>msg 925</comment>
        <translation>Pls input super admi or hight user's rights:</translation>
    </message>
    <message>
        <source>Pls input admi or hight user's rights:</source>
        <comment>msg 924</comment>
        <translation>Pls input admi or hight user's rights:</translation>
    </message>
    <message>
        <source>Pls input operator or hight user's rights:</source>
        <comment>msg 923</comment>
        <translation>Pls input operator or hight user's rights:</translation>
    </message>
    <message>
        <source>Incorrect password!</source>
        <comment>msg 905</comment>
        <translation>Incorrect password!</translation>
    </message>
    <message>
        <source>User level: %1</source>
        <translation>User level: %1</translation>
    </message>
    <message>
        <source>Change user level (0 %1, 1 %2, 2 %3, 3 %4):</source>
        <translation>Change user level (0 %1, 1 %2, 2 %3, 3 %4):</translation>
    </message>
    <message>
        <source>Enter 0, 1, 2 or 3</source>
        <translation>Enter 0, 1, 2 or 3</translation>
    </message>
    <message>
        <source>Rights is limited,pls shift user's rights:</source>
        <comment>msg 934</comment>
        <translation>Rights is limited,pls shift user's rights:</translation>
    </message>
    <message>
        <source>Pls input new password:</source>
        <comment>msg 922</comment>
        <translation>Pls input new password:</translation>
    </message>
    <message>
        <source>The No. of characters &lt; 6,pls input again!</source>
        <comment>msg 918</comment>
        <translation>The No. of characters &lt; 6,pls input again!</translation>
    </message>
    <message>
        <source>Pls input password again:</source>
        <comment>msg 921</comment>
        <translation>Pls input password again:</translation>
    </message>
    <message>
        <source>Two entries are not the same,pls input again!</source>
        <comment>msg 919</comment>
        <translation>Two entries are not the same,pls input again!</translation>
    </message>
    <message>
        <source>Successfully modified!</source>
        <comment>msg 920</comment>
        <translation>Successfully modified!</translation>
    </message>
</context>
<context>
    <name>m350::ui::LogPage</name>
    <message>
        <source>System Log</source>
        <comment>msg 304</comment>
        <translation>System Log</translation>
    </message>
    <message>
        <source>Time</source>
        <comment>msg 100</comment>
        <translation>Time</translation>
    </message>
    <message>
        <source>Event</source>
        <comment>msg 101</comment>
        <translation>Event</translation>
    </message>
    <message>
        <source>Start working</source>
        <comment>msg 112</comment>
        <translation>Start working</translation>
    </message>
    <message>
        <source>Resume</source>
        <comment>msg 113</comment>
        <translation>Resume</translation>
    </message>
    <message>
        <source>Pause</source>
        <comment>msg 114</comment>
        <translation>Pause</translation>
    </message>
    <message>
        <source>MDI</source>
        <comment>msg 129</comment>
        <translation>MDI</translation>
    </message>
    <message>
        <source>Hook file run</source>
        <translation>Hook file run</translation>
    </message>
    <message>
        <source>Probe</source>
        <comment>msg 108</comment>
        <translation>Probe</translation>
    </message>
    <message>
        <source>Home All Axes</source>
        <comment>msg 107</comment>
        <translation>Home All Axes</translation>
    </message>
    <message>
        <source>Axis mach zero</source>
        <comment>msg 119</comment>
        <translation>Axis mach zero</translation>
    </message>
    <message>
        <source>All axis clear</source>
        <comment>msg 120</comment>
        <translation>All axis clear</translation>
    </message>
    <message>
        <source>Axis Coord set</source>
        <comment>msg 118</comment>
        <translation>Axis Coord set</translation>
    </message>
    <message>
        <source>All axes go to zero</source>
        <comment>msg 115</comment>
        <translation>All axes go to zero</translation>
    </message>
    <message>
        <source>Axes Middle</source>
        <comment>msg 109</comment>
        <translation>Axes Middle</translation>
    </message>
    <message>
        <source>Start Simulating</source>
        <comment>msg 111</comment>
        <translation>Start Simulating</translation>
    </message>
    <message>
        <source>SL over</source>
        <comment>msg 125</comment>
        <translation>SL over</translation>
    </message>
    <message>
        <source>Select file</source>
        <comment>msg 110</comment>
        <translation>Select file</translation>
    </message>
    <message>
        <source>Line start</source>
        <comment>msg 126</comment>
        <translation>Line start</translation>
    </message>
    <message>
        <source>Break run</source>
        <comment>msg 128</comment>
        <translation>Break run</translation>
    </message>
    <message>
        <source>RESET</source>
        <comment>msg 22</comment>
        <translation>RESET</translation>
    </message>
    <message>
        <source>ESP</source>
        <comment>msg 749</comment>
        <translation>ESP</translation>
    </message>
    <message>
        <source>ERROR</source>
        <comment>msg 23</comment>
        <translation>ERROR</translation>
    </message>
    <message>
        <source>Parameter changed</source>
        <translation>Parameter changed</translation>
    </message>
    <message>
        <source>Parameter changed (Guest)</source>
        <translation>Parameter changed (Guest)</translation>
    </message>
    <message>
        <source>Parameter changed (Operator)</source>
        <translation>Parameter changed (Operator)</translation>
    </message>
    <message>
        <source>Parameter changed (Admin)</source>
        <translation>Parameter changed (Admin)</translation>
    </message>
    <message>
        <source>Parameter changed (Super)</source>
        <translation>Parameter changed (Super)</translation>
    </message>
    <message>
        <source>passwords.toml cannot be trusted: only Guest opens until it is repaired</source>
        <translation>passwords.toml cannot be trusted: only Guest opens until it is repaired</translation>
    </message>
    <message>
        <source>Passwords reset to their defaults (m350-sim reset-passwords)</source>
        <translation>Passwords reset to their defaults (m350-sim reset-passwords)</translation>
    </message>
    <message>
        <source>Variable changed</source>
        <translation>Variable changed</translation>
    </message>
    <message>
        <source>Output switched</source>
        <translation>Output switched</translation>
    </message>
    <message>
        <source>Simulator: input fault</source>
        <translation>Simulator: input fault</translation>
    </message>
    <message>
        <source>User level changed</source>
        <translation>User level changed</translation>
    </message>
    <message>
        <source>Clear Record</source>
        <comment>msg 548</comment>
        <translation>Clear Record</translation>
    </message>
    <message>
        <source>Tool table changed</source>
        <translation>Tool table changed</translation>
    </message>
    <message>
        <source>Tool touched off</source>
        <translation>Tool touched off</translation>
    </message>
    <message>
        <source>Set target tool No.:</source>
        <comment>msg 883</comment>
        <translation>Set target tool No.:</translation>
    </message>
    <message>
        <source>Tool life reset</source>
        <translation>Tool life reset</translation>
    </message>
    <message>
        <source>DPRNT output</source>
        <translation>DPRNT output</translation>
    </message>
    <message>
        <source>DPRNT output reached its limit; dprnt.txt keeps the first and the last records</source>
        <translation>DPRNT output reached its limit; dprnt.txt keeps the first and the last records</translation>
    </message>
    <message>
        <source>DPRNT records not logged (sent faster than the log takes them)</source>
        <translation>DPRNT records not logged (sent faster than the log takes them)</translation>
    </message>
    <message>
        <source>The System Log is not saved: %1</source>
        <translation>The System Log is not saved: %1</translation>
    </message>
</context>
<context>
    <name>m350::ui::MachineView</name>
    <message>
        <source>X-Y  Top view</source>
        <translation>X-Y  Top view</translation>
    </message>
    <message>
        <source>X-Z  Front view</source>
        <translation>X-Z  Front view</translation>
    </message>
    <message>
        <source>Building the preview...</source>
        <translation>Building the preview...</translation>
    </message>
    <message>
        <source>%1 moves</source>
        <translation>%1 moves</translation>
    </message>
    <message>
        <source>Simplified to %1 mm (memory budget)</source>
        <translation>Simplified to %1 mm (memory budget)</translation>
    </message>
    <message>
        <source>The program has errors: no path</source>
        <translation>The program has errors: no path</translation>
    </message>
    <message>
        <source>No program path</source>
        <translation>No program path</translation>
    </message>
</context>
<context>
    <name>m350::ui::MainWindow</name>
    <message>
        <source>Recording stopped: %1</source>
        <translation>Recording stopped: %1</translation>
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
        <source>Set target tool No.:</source>
        <comment>msg 883</comment>
        <translation>Set target tool No.:</translation>
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
        <source>%1 is inside the machine folder %2: refused, nothing was written</source>
        <translation>%1 is inside the machine folder %2: refused, nothing was written</translation>
    </message>
    <message>
        <source>%1 is the loaded program: refused, nothing was written</source>
        <translation>%1 is the loaded program: refused, nothing was written</translation>
    </message>
    <message>
        <source>%1 is a folder, not a file: refused, nothing was written</source>
        <translation>%1 is a folder, not a file: refused, nothing was written</translation>
    </message>
    <message>
        <source>%1 is a socket, not a file: refused, nothing was written</source>
        <translation>%1 is a socket, not a file: refused, nothing was written</translation>
    </message>
    <message>
        <source>%1 is a disk (block device), not a file: refused, nothing was written</source>
        <translation>%1 is a disk (block device), not a file: refused, nothing was written</translation>
    </message>
    <message>
        <source>%1: its folder does not exist or is not a folder: refused, nothing was written</source>
        <translation>%1: its folder does not exist or is not a folder: refused, nothing was written</translation>
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
    <message>
        <source>Import controller backup...</source>
        <translation>Import controller backup...</translation>
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
    <name>m350::ui::MiddlePage</name>
    <message>
        <source>Middle</source>
        <comment>msg 321</comment>
        <translation>Middle</translation>
    </message>
    <message>
        <source>Set 1</source>
        <comment>msg 524</comment>
        <translation>Set 1</translation>
    </message>
    <message>
        <source>Set 2</source>
        <comment>msg 525</comment>
        <translation>Set 2</translation>
    </message>
    <message>
        <source>Middle</source>
        <comment>msg 526</comment>
        <translation>Middle</translation>
    </message>
    <message>
        <source>4pts</source>
        <comment>msg 529</comment>
        <translation>4pts</translation>
    </message>
    <message>
        <source>Set X</source>
        <comment>msg 512</comment>
        <translation>Set X</translation>
    </message>
    <message>
        <source>Middle X</source>
        <comment>msg 513</comment>
        <translation>Middle X</translation>
    </message>
    <message>
        <source>Set Y</source>
        <comment>msg 514</comment>
        <translation>Set Y</translation>
    </message>
    <message>
        <source>Middle Y</source>
        <comment>msg 515</comment>
        <translation>Middle Y</translation>
    </message>
    <message>
        <source>3Pts</source>
        <comment>msg 517</comment>
        <translation>3Pts</translation>
    </message>
    <message>
        <source>Press [Set X] at the first side first</source>
        <translation>Press [Set X] at the first side first</translation>
    </message>
    <message>
        <source>Press [Set Y] at the first side first</source>
        <translation>Press [Set Y] at the first side first</translation>
    </message>
    <message>
        <source>Record two points of the circle first ([Set 1], [Set 2])</source>
        <translation>Record two points of the circle first ([Set 1], [Set 2])</translation>
    </message>
    <message>
        <source>The three points lie on a line: no circle through them</source>
        <translation>The three points lie on a line: no circle through them</translation>
    </message>
    <message>
        <source>Arc 3 pts:</source>
        <comment>msg 964</comment>
        <translation>Arc 3 pts:</translation>
    </message>
    <message>
        <source>First pts:</source>
        <comment>msg 968</comment>
        <translation>First pts:</translation>
    </message>
    <message>
        <source>Second pts:</source>
        <comment>msg 969</comment>
        <translation>Second pts:</translation>
    </message>
    <message>
        <source>Third pts:</source>
        <comment>msg 970</comment>
        <translation>Third pts:</translation>
    </message>
    <message>
        <source>Center:</source>
        <comment>msg 971</comment>
        <translation>Center:</translation>
    </message>
    <message>
        <source>1:Move to the first point and press [Set 1];</source>
        <comment>msg 965</comment>
        <translation>1:Move to the first point and press [Set 1];</translation>
    </message>
    <message>
        <source>2:Move to the second point and press [Set 2];</source>
        <comment>msg 966</comment>
        <translation>2:Move to the second point and press [Set 2];</translation>
    </message>
    <message>
        <source>3:Move to the third point and press[Middle],get center of arc and set it to zero;</source>
        <comment>msg 967</comment>
        <translation>3:Move to the third point and press[Middle],get center of arc and set it to zero;</translation>
    </message>
    <message>
        <source>4 Pts:</source>
        <comment>msg 972</comment>
        <translation>4 Pts:</translation>
    </message>
    <message>
        <source>Px1:</source>
        <comment>msg 976</comment>
        <translation>Px1:</translation>
    </message>
    <message>
        <source>Px2:</source>
        <comment>msg 977</comment>
        <translation>Px2:</translation>
    </message>
    <message>
        <source>Pxm:</source>
        <comment>msg 978</comment>
        <translation>Pxm:</translation>
    </message>
    <message>
        <source>Py1:</source>
        <comment>msg 979</comment>
        <translation>Py1:</translation>
    </message>
    <message>
        <source>Py2</source>
        <comment>msg 980</comment>
        <translation>Py2</translation>
    </message>
    <message>
        <source>Pym:</source>
        <comment>msg 981</comment>
        <translation>Pym:</translation>
    </message>
    <message>
        <source>Mannal Center Operation(X):</source>
        <comment>msg 973</comment>
        <translation>Mannal Center Operation(X):</translation>
    </message>
    <message>
        <source>1:Take the tool to the point Px1 and press [Set X] to set;</source>
        <comment>msg 974</comment>
        <translation>1:Take the tool to the point Px1 and press [Set X] to set;</translation>
    </message>
    <message>
        <source>2:Take the tool to the point Px2 and press [Middle X],get  midpoint and set the X zero;</source>
        <comment>msg 975</comment>
        <translation>2:Take the tool to the point Px2 and press [Middle X],get  midpoint and set the X zero;</translation>
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
        <source>Not in the simulator</source>
        <translation>Not in the simulator</translation>
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
    <message>
        <source>deg</source>
        <translation>deg</translation>
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
        <translation>Param</translation>
    </message>
    <message>
        <source>Param List</source>
        <comment>msg 384</comment>
        <translation>Param List</translation>
    </message>
    <message>
        <source>Search</source>
        <comment>msg 385</comment>
        <translation>Search</translation>
    </message>
    <message>
        <source>Param Backup</source>
        <comment>msg 386</comment>
        <translation>Param Backup</translation>
    </message>
    <message>
        <source>Param Restore</source>
        <comment>msg 387</comment>
        <translation>Param Restore</translation>
    </message>
    <message>
        <source>#50-#499</source>
        <comment>msg 388</comment>
        <translation>#50-#499</translation>
    </message>
    <message>
        <source>Factory(N)</source>
        <comment>msg 949</comment>
        <translation>Factory(N)</translation>
    </message>
    <message>
        <source>User(O)</source>
        <comment>msg 950</comment>
        <translation>User(O)</translation>
    </message>
    <message>
        <source>User level</source>
        <translation>User level</translation>
    </message>
    <message>
        <source>Machine</source>
        <comment>msg 64</comment>
        <translation>Machine</translation>
    </message>
    <message>
        <source>Manual</source>
        <comment>msg 65</comment>
        <translation>Manual</translation>
    </message>
    <message>
        <source>Process</source>
        <comment>msg 66</comment>
        <translation>Process</translation>
    </message>
    <message>
        <source>Coordinate</source>
        <comment>msg 67</comment>
        <translation>Coordinate</translation>
    </message>
    <message>
        <source>Spindle</source>
        <comment>msg 68</comment>
        <translation>Spindle</translation>
    </message>
    <message>
        <source>IO</source>
        <comment>msg 69</comment>
        <translation>IO</translation>
    </message>
    <message>
        <source>Home</source>
        <comment>msg 70</comment>
        <translation>Home</translation>
    </message>
    <message>
        <source>Probe</source>
        <comment>msg 71</comment>
        <translation>Probe</translation>
    </message>
    <message>
        <source>Hard Limit</source>
        <comment>msg 72</comment>
        <translation>Hard Limit</translation>
    </message>
    <message>
        <source>Software limit</source>
        <comment>msg 73</comment>
        <translation>Software limit</translation>
    </message>
    <message>
        <source>MPG</source>
        <comment>msg 74</comment>
        <translation>MPG</translation>
    </message>
    <message>
        <source>External</source>
        <comment>msg 75</comment>
        <translation>External</translation>
    </message>
    <message>
        <source>Backlash</source>
        <comment>msg 76</comment>
        <translation>Backlash</translation>
    </message>
    <message>
        <source>Tools</source>
        <comment>msg 77</comment>
        <translation>Tools</translation>
    </message>
    <message>
        <source>System</source>
        <comment>msg 78</comment>
        <translation>System</translation>
    </message>
    <message>
        <source>Input ports</source>
        <translation>Input ports</translation>
    </message>
    <message>
        <source>Output ports</source>
        <translation>Output ports</translation>
    </message>
    <message>
        <source>Not on the firmware's pages</source>
        <translation>Not on the firmware's pages</translation>
    </message>
    <message>
        <source>No.</source>
        <comment>msg 83</comment>
        <translation>No.</translation>
    </message>
    <message>
        <source>Note</source>
        <comment>msg 84</comment>
        <translation>Note</translation>
    </message>
    <message>
        <source>Value</source>
        <comment>msg 85</comment>
        <translation>Value</translation>
    </message>
    <message>
        <source>Unit</source>
        <comment>msg 86</comment>
        <translation>Unit</translation>
    </message>
    <message>
        <source>Macro variables #50-#499, as a program reads them</source>
        <translation>Macro variables #50-#499, as a program reads them</translation>
    </message>
    <message>
        <source>(now: %1)</source>
        <translation>(now: %1)</translation>
    </message>
    <message>
        <source>User:</source>
        <comment>msg 940</comment>
        <translation>User:</translation>
    </message>
    <message>
        <source>Enter sets the selected variable, as a macro's #%1 = value would.</source>
        <translation>Enter sets the selected variable, as a macro's #%1 = value would.</translation>
    </message>
    <message>
        <source>Param List:</source>
        <comment>msg 941</comment>
        <translation>Param List:</translation>
    </message>
    <message>
        <source>Details:</source>
        <comment>msg 946</comment>
        <translation>Details:</translation>
    </message>
    <message>
        <source>macro #%1, factory value %2</source>
        <translation>macro #%1, factory value %2</translation>
    </message>
    <message>
        <source>Active:</source>
        <comment>msg 947</comment>
        <translation>Active:</translation>
    </message>
    <message>
        <source>Immediately</source>
        <comment>msg 913</comment>
        <translation>Immediately</translation>
    </message>
    <message>
        <source>Range:</source>
        <comment>msg 948</comment>
        <translation>Range:</translation>
    </message>
    <message>
        <source>[%d]The data entered is illegal!</source>
        <comment>msg 802</comment>
        <translation>[%d]The data entered is illegal!</translation>
    </message>
    <message>
        <source>Variable #%1: not a number</source>
        <translation>Variable #%1: not a number</translation>
    </message>
    <message>
        <source>Input searching parameter No. :</source>
        <comment>msg 935</comment>
        <translation>Input searching parameter No. :</translation>
    </message>
    <message>
        <source>Parameter %1 is not on the parameter pages</source>
        <translation>Parameter %1 is not on the parameter pages</translation>
    </message>
    <message>
        <source>File save failed!</source>
        <comment>msg 907</comment>
        <translation>File save failed!</translation>
    </message>
    <message>
        <source>Parameters backed up to %1</source>
        <translation>Parameters backed up to %1</translation>
    </message>
    <message>
        <source>No backup: %1 does not exist (Param Backup writes it)</source>
        <translation>No backup: %1 does not exist (Param Backup writes it)</translation>
    </message>
    <message>
        <source>Restore every parameter from %1?</source>
        <translation>Restore every parameter from %1?</translation>
    </message>
    <message>
        <source>Parameter restore refused, nothing changed: %1</source>
        <translation>Parameter restore refused, nothing changed: %1</translation>
    </message>
    <message>
        <source>Parameters restored from %1: %2 changed</source>
        <translation>Parameters restored from %1: %2 changed</translation>
    </message>
    <message>
        <source>; %1 outside their ranges kept as saved</source>
        <translation>; %1 outside their ranges kept as saved</translation>
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
        <source>Tool Table</source>
        <translation>Tool Table</translation>
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
    <name>m350::ui::ProgramEditor</name>
    <message>
        <source>File is too large to edit</source>
        <comment>msg 137</comment>
        <translation>File is too large to edit</translation>
    </message>
    <message>
        <source>Current File:</source>
        <comment>msg 953</comment>
        <translation>Current File:</translation>
    </message>
    <message>
        <source>... %1 more</source>
        <translation>... %1 more</translation>
    </message>
</context>
<context>
    <name>m350::ui::ProgramList</name>
    <message>
        <source>Local Disk(O)</source>
        <comment>msg 959</comment>
        <translation>Local Disk(O)</translation>
    </message>
    <message>
        <source>U Disk(N)</source>
        <comment>msg 960</comment>
        <translation>U Disk(N)</translation>
    </message>
    <message>
        <source>System disk (macro libraries)</source>
        <translation>System disk (macro libraries)</translation>
    </message>
    <message>
        <source>Name</source>
        <comment>msg 80</comment>
        <translation>Name</translation>
    </message>
    <message>
        <source>Size</source>
        <comment>msg 81</comment>
        <translation>Size</translation>
    </message>
    <message>
        <source>Modify time</source>
        <comment>msg 82</comment>
        <translation>Modify time</translation>
    </message>
    <message>
        <source>Cur Path:</source>
        <comment>msg 952</comment>
        <translation>Cur Path:</translation>
    </message>
    <message>
        <source>EXT</source>
        <comment>msg 757</comment>
        <translation>EXT</translation>
    </message>
    <message>
        <source>DATE</source>
        <comment>msg 758</comment>
        <translation>DATE</translation>
    </message>
    <message>
        <source>NAME</source>
        <comment>msg 756</comment>
        <translation>NAME</translation>
    </message>
    <message>
        <source>Free Space:</source>
        <comment>msg 951</comment>
        <translation>Free Space:</translation>
    </message>
    <message>
        <source>Sort:</source>
        <comment>msg 759</comment>
        <translation>Sort:</translation>
    </message>
</context>
<context>
    <name>m350::ui::ProgramPage</name>
    <message>
        <source>Program</source>
        <comment>msg 301</comment>
        <translation>Program</translation>
    </message>
    <message>
        <source>Not in the simulator</source>
        <translation>Not in the simulator</translation>
    </message>
    <message>
        <source>Save Exit</source>
        <comment>msg 336</comment>
        <translation>Save Exit</translation>
    </message>
    <message>
        <source>Find Line</source>
        <comment>msg 337</comment>
        <translation>Find Line</translation>
    </message>
    <message>
        <source>Del Line</source>
        <comment>msg 338</comment>
        <translation>Del Line</translation>
    </message>
    <message>
        <source>CAM</source>
        <comment>msg 340</comment>
        <translation>CAM</translation>
    </message>
    <message>
        <source>Teaching</source>
        <comment>msg 341</comment>
        <translation>Teaching</translation>
    </message>
    <message>
        <source>Speed %1</source>
        <translation>Speed %1</translation>
    </message>
    <message>
        <source>Simulate</source>
        <comment>msg 332</comment>
        <translation>Simulate</translation>
    </message>
    <message>
        <source>Esc</source>
        <comment>msg 939</comment>
        <translation>Esc</translation>
    </message>
    <message>
        <source>The macro libraries are edited here, not deleted, renamed or run</source>
        <translation>The macro libraries are edited here, not deleted, renamed or run</translation>
    </message>
    <message>
        <source>Copy To Local</source>
        <comment>msg 958</comment>
        <translation>Copy To Local</translation>
    </message>
    <message>
        <source>Copy To U Disk</source>
        <comment>msg 327</comment>
        <translation>Copy To U Disk</translation>
    </message>
    <message>
        <source>Switch disks</source>
        <comment>msg 324</comment>
        <translation>Switch disks</translation>
    </message>
    <message>
        <source>Del</source>
        <comment>msg 325</comment>
        <translation>Del</translation>
    </message>
    <message>
        <source>Rename</source>
        <comment>msg 326</comment>
        <translation>Rename</translation>
    </message>
    <message>
        <source>New</source>
        <comment>msg 328</comment>
        <translation>New</translation>
    </message>
    <message>
        <source>Edit</source>
        <comment>msg 329</comment>
        <translation>Edit</translation>
    </message>
    <message>
        <source>Copy</source>
        <comment>msg 330</comment>
        <translation>Copy</translation>
    </message>
    <message>
        <source>Paste</source>
        <comment>msg 331</comment>
        <translation>Paste</translation>
    </message>
    <message>
        <source>Load NC</source>
        <comment>msg 333</comment>
        <translation>Load NC</translation>
    </message>
    <message>
        <source>Clear local</source>
        <comment>msg 334</comment>
        <translation>Clear local</translation>
    </message>
    <message>
        <source>Sort</source>
        <comment>msg 335</comment>
        <translation>Sort</translation>
    </message>
    <message>
        <source>Select file</source>
        <comment>msg 110</comment>
        <translation>Select file</translation>
    </message>
    <message>
        <source>File save failed!</source>
        <comment>msg 907</comment>
        <translation>File save failed!</translation>
    </message>
    <message>
        <source>Pls input searching line No:</source>
        <comment>msg 894</comment>
        <translation>Pls input searching line No:</translation>
    </message>
    <message>
        <source>[Enter] to save,[Esc] is not to save.</source>
        <comment>msg 893</comment>
        <translation>[Enter] to save,[Esc] is not to save.</translation>
    </message>
    <message>
        <source>File name is too long!</source>
        <comment>msg 797</comment>
        <translation>File name is too long!</translation>
    </message>
    <message>
        <source>File exists, please re-enter!</source>
        <comment>msg 803</comment>
        <translation>File exists, please re-enter!</translation>
    </message>
    <message>
        <source>A file name may not begin with a dot or hold / : * ? &lt; &gt; | or a quote</source>
        <translation>A file name may not begin with a dot or hold / : * ? &lt; &gt; | or a quote</translation>
    </message>
    <message>
        <source>Pls enter the file name:</source>
        <comment>msg 804</comment>
        <translation>Pls enter the file name:</translation>
    </message>
    <message>
        <source>Current file is running,can't delete!</source>
        <comment>msg 871</comment>
        <translation>Current file is running,can't delete!</translation>
    </message>
    <message>
        <source>Do you want to delete the selected file?</source>
        <comment>msg 957</comment>
        <translation>Do you want to delete the selected file?</translation>
    </message>
    <message>
        <source>file does not exist!</source>
        <comment>msg 842</comment>
        <translation>file does not exist!</translation>
    </message>
    <message>
        <source>Copy successful!</source>
        <comment>msg 955</comment>
        <translation>Copy successful!</translation>
    </message>
    <message>
        <source>Delete all?</source>
        <comment>msg 846</comment>
        <translation>Delete all?</translation>
    </message>
</context>
<context>
    <name>m350::ui::ProgramWindow</name>
    <message>
        <source>No program loaded</source>
        <translation>No program loaded</translation>
    </message>
    <message>
        <source>%1: cannot be read</source>
        <translation>%1: cannot be read</translation>
    </message>
    <message>
        <source>%1   Line %2</source>
        <translation>%1   Line %2</translation>
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
    <name>m350::ui::RecordPage</name>
    <message>
        <source>Work Record</source>
        <comment>msg 322</comment>
        <translation>Work Record</translation>
    </message>
    <message>
        <source>Clear Record</source>
        <comment>msg 548</comment>
        <translation>Clear Record</translation>
    </message>
    <message>
        <source>To U Disk</source>
        <comment>msg 549</comment>
        <translation>To U Disk</translation>
    </message>
    <message>
        <source>Confirm to delete the working record?</source>
        <comment>msg 875</comment>
        <translation>Confirm to delete the working record?</translation>
    </message>
    <message>
        <source>%1: cannot write: %2</source>
        <translation>%1: cannot write: %2</translation>
    </message>
    <message>
        <source>Working record saved to %1</source>
        <translation>Working record saved to %1</translation>
    </message>
    <message>
        <source>Current file:</source>
        <comment>msg 876</comment>
        <translation>Current file:</translation>
    </message>
    <message>
        <source>Total No.</source>
        <comment>msg 47</comment>
        <translation>Total No.</translation>
    </message>
    <message>
        <source>Finished No.:</source>
        <comment>msg 878</comment>
        <translation>Finished No.:</translation>
    </message>
    <message>
        <source>Time per:</source>
        <comment>msg 879</comment>
        <translation>Time per:</translation>
    </message>
    <message>
        <source>Total time:</source>
        <comment>msg 880</comment>
        <translation>Total time:</translation>
    </message>
    <message>
        <source>Start date:</source>
        <comment>msg 881</comment>
        <translation>Start date:</translation>
    </message>
</context>
<context>
    <name>m350::ui::ReviewBar</name>
    <message>
        <source>%1 / %2 s</source>
        <translation>%1 / %2 s</translation>
    </message>
    <message>
        <source>End of the attempt</source>
        <translation>End of the attempt</translation>
    </message>
    <message>
        <source>Next: %1 s hand in</source>
        <translation>Next: %1 s hand in</translation>
    </message>
    <message>
        <source>Next: %1 s %2</source>
        <translation>Next: %1 s %2</translation>
    </message>
    <message>
        <source>key %1</source>
        <translation>key %1</translation>
    </message>
    <message>
        <source>key %1 held</source>
        <translation>key %1 held</translation>
    </message>
    <message>
        <source>key %1 let go</source>
        <translation>key %1 let go</translation>
    </message>
    <message>
        <source>types "%1"</source>
        <translation>types "%1"</translation>
    </message>
    <message>
        <source>handwheel %1 detents</source>
        <translation>handwheel %1 detents</translation>
    </message>
    <message>
        <source>page %1</source>
        <translation>page %1</translation>
    </message>
    <message>
        <source>fault IN%1 %2</source>
        <translation>fault IN%1 %2</translation>
    </message>
    <message>
        <source>language %1</source>
        <translation>language %1</translation>
    </message>
    <message>
        <source>load %1</source>
        <translation>load %1</translation>
    </message>
    <message>
        <source>time passes</source>
        <translation>time passes</translation>
    </message>
    <message>
        <source>Pause (Space)</source>
        <translation>Pause (Space)</translation>
    </message>
    <message>
        <source>Play (Space)</source>
        <translation>Play (Space)</translation>
    </message>
    <message>
        <source>Block (.)</source>
        <translation>Block (.)</translation>
    </message>
    <message>
        <source>%1 (F8)</source>
        <translation>%1 (F8)</translation>
    </message>
</context>
<context>
    <name>m350::ui::ReviewWindow</name>
    <message>
        <source>no folder for the attempt's machine: %1</source>
        <translation>no folder for the attempt's machine: %1</translation>
    </message>
    <message>
        <source>Follow the run</source>
        <translation>Follow the run</translation>
    </message>
    <message>
        <source>Machine view</source>
        <translation>Machine view</translation>
    </message>
    <message>
        <source>Panel</source>
        <translation>Panel</translation>
    </message>
    <message>
        <source>(no name)</source>
        <translation>(no name)</translation>
    </message>
    <message>
        <source>Review: %1 · %2</source>
        <translation>Review: %1 · %2</translation>
    </message>
    <message>
        <source>Handed in: passed</source>
        <translation>Handed in: passed</translation>
    </message>
    <message>
        <source>Handed in: failed (%1)</source>
        <translation>Handed in: failed (%1)</translation>
    </message>
</context>
<context>
    <name>m350::ui::RunningProgramView</name>
    <message>
        <source>No program has run yet</source>
        <translation>No program has run yet</translation>
    </message>
    <message>
        <source>%1: cannot be read</source>
        <translation>%1: cannot be read</translation>
    </message>
    <message>
        <source>%1   Line %2</source>
        <translation>%1   Line %2</translation>
    </message>
    <message>
        <source>%1   (not running)</source>
        <translation>%1   (not running)</translation>
    </message>
</context>
<context>
    <name>m350::ui::SessionWorker</name>
    <message>
        <source>No program loaded: load one on the Program page</source>
        <translation>No program loaded: load one on the Program page</translation>
    </message>
    <message>
        <source>A program is running: wait for it, or PAUSE / RESET first</source>
        <translation>A program is running: wait for it, or PAUSE / RESET first</translation>
    </message>
    <message>
        <source>Set target tool No.:</source>
        <comment>msg 883</comment>
        <translation>Set target tool No.:</translation>
    </message>
    <message>
        <source>Parameter %1: invalid value</source>
        <translation>Parameter %1: invalid value</translation>
    </message>
    <message>
        <source>Line %1 is not in the program</source>
        <translation>Line %1 is not in the program</translation>
    </message>
    <message>
        <source>No paused run to resume (PAUSE, then RESET)</source>
        <translation>No paused run to resume (PAUSE, then RESET)</translation>
    </message>
    <message>
        <source>No break point is kept in the machine folder</source>
        <translation>No break point is kept in the machine folder</translation>
    </message>
    <message>
        <source>External key %1</source>
        <translation>External key %1</translation>
    </message>
    <message>
        <source>%1 stands for the panel key %2, which this panel does not press for it</source>
        <translation>%1 stands for the panel key %2, which this panel does not press for it</translation>
    </message>
    <message>
        <source>IN%1: no such input (IN01-IN24)</source>
        <translation>IN%1: no such input (IN01-IN24)</translation>
    </message>
    <message>
        <source>File save failed!</source>
        <comment>msg 907</comment>
        <translation>File save failed!</translation>
    </message>
</context>
<context>
    <name>m350::ui::SimulationPanel</name>
    <message>
        <source>Max</source>
        <translation>Max</translation>
    </message>
    <message>
        <source>SL over</source>
        <comment>msg 125</comment>
        <translation>SL over</translation>
    </message>
    <message>
        <source>Start Simulating</source>
        <comment>msg 111</comment>
        <translation>Start Simulating</translation>
    </message>
    <message>
        <source>%1  speed %2  line %3  %4 s  %5 blocks  %6 points</source>
        <translation>%1  speed %2  line %3  %4 s  %5 blocks  %6 points</translation>
    </message>
</context>
<context>
    <name>m350::ui::SystemPage</name>
    <message>
        <source>System Info</source>
        <comment>msg 305</comment>
        <translation>System Info</translation>
    </message>
    <message>
        <source>Registration</source>
        <comment>msg 536</comment>
        <translation>Registration</translation>
    </message>
    <message>
        <source>The simulator needs no licence</source>
        <translation>The simulator needs no licence</translation>
    </message>
    <message>
        <source>Password Set</source>
        <comment>msg 537</comment>
        <translation>Password Set</translation>
    </message>
    <message>
        <source>System Update</source>
        <comment>msg 538</comment>
        <translation>System Update</translation>
    </message>
    <message>
        <source>A new version is a new build of M350 Studio</source>
        <translation>A new version is a new build of M350 Studio</translation>
    </message>
    <message>
        <source>System Set</source>
        <comment>msg 539</comment>
        <translation>System Set</translation>
    </message>
    <message>
        <source>Date, network and factory reset belong to the controller's system, which is not simulated</source>
        <translation>Date, network and factory reset belong to the controller's system, which is not simulated</translation>
    </message>
    <message>
        <source>System BackUp</source>
        <comment>msg 540</comment>
        <translation>System BackUp</translation>
    </message>
    <message>
        <source>Copy the machine folder to keep the whole machine</source>
        <translation>Copy the machine folder to keep the whole machine</translation>
    </message>
    <message>
        <source>User level</source>
        <translation>User level</translation>
    </message>
    <message>
        <source>System Name:</source>
        <comment>msg 930</comment>
        <translation>System Name:</translation>
    </message>
    <message>
        <source>Software Ver:</source>
        <comment>msg 928</comment>
        <translation>Software Ver:</translation>
    </message>
    <message>
        <source>Machine:</source>
        <translation>Machine:</translation>
    </message>
    <message>
        <source>Machine folder:</source>
        <translation>Machine folder:</translation>
    </message>
    <message>
        <source>Parameters:</source>
        <translation>Parameters:</translation>
    </message>
    <message>
        <source>Programs:</source>
        <translation>Programs:</translation>
    </message>
    <message>
        <source>User level:</source>
        <translation>User level:</translation>
    </message>
    <message>
        <source>Passwords:</source>
        <translation>Passwords:</translation>
    </message>
    <message>
        <source>M350 Studio (a DDCS M350 panel simulator)</source>
        <translation>M350 Studio (a DDCS M350 panel simulator)</translation>
    </message>
    <message>
        <source>%1 catalogued, %2 on the Param page</source>
        <translation>%1 catalogued, %2 on the Param page</translation>
    </message>
    <message>
        <source>%1 .nc files in the machine folder</source>
        <translation>%1 .nc files in the machine folder</translation>
    </message>
    <message>
        <source>passwords.toml in order</source>
        <translation>passwords.toml in order</translation>
    </message>
    <message>
        <source>Locked: passwords.toml cannot be trusted (%1), so only %2 opens and no default password comes back. Repair: set new passwords at the highest level, or run m350-sim reset-passwords --config FOLDER</source>
        <translation>Locked: passwords.toml cannot be trusted (%1), so only %2 opens and no default password comes back. Repair: set new passwords at the highest level, or run m350-sim reset-passwords --config FOLDER</translation>
    </message>
</context>
<context>
    <name>m350::ui::ToolLifePage</name>
    <message>
        <source>Tool Life</source>
        <translation>Tool Life</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Group</translation>
    </message>
    <message>
        <source>Life type</source>
        <translation>Life type</translation>
    </message>
    <message>
        <source>Life</source>
        <translation>Life</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Tool</translation>
    </message>
    <message>
        <source>Used</source>
        <translation>Used</translation>
    </message>
    <message>
        <source>Remaining</source>
        <translation>Remaining</translation>
    </message>
    <message>
        <source>State</source>
        <translation>State</translation>
    </message>
    <message>
        <source>UP/DOWN: tool (and its group). Reset Life: the group's tools start again from 0 used. Minutes count cutting feed only (no rapids, dwells, holds or tool changes), in whole 4 s units, shown as min:s. @ in use, # life reached.</source>
        <translation>UP/DOWN: tool (and its group). Reset Life: the group's tools start again from 0 used. Minutes count cutting feed only (no rapids, dwells, holds or tool changes), in whole 4 s units, shown as min:s. @ in use, # life reached.</translation>
    </message>
    <message>
        <source>Reset Life</source>
        <translation>Reset Life</translation>
    </message>
    <message>
        <source>No tool life groups</source>
        <translation>No tool life groups</translation>
    </message>
    <message>
        <source>Tool Table</source>
        <translation>Tool Table</translation>
    </message>
    <message>
        <source>Simulator extra: the M350 itself has no tool life management. Here T%1+n selects group n (T%2 = group 1) and the T word changes the tool, as M06 does on FANUC.</source>
        <translation>Simulator extra: the M350 itself has no tool life management. Here T%1+n selects group n (T%2 = group 1) and the T word changes the tool, as M06 does on FANUC.</translation>
    </message>
    <message>
        <source>FANUC 0i: T%1 selects group 1 (the ignore number plus the group); M06 ends the counting of the old tool and starts it for the selected one.</source>
        <translation>FANUC 0i: T%1 selects group 1 (the ignore number plus the group); M06 ends the counting of the old tool and starts it for the selected one.</translation>
    </message>
    <message>
        <source>In use, life reached</source>
        <translation>In use, life reached</translation>
    </message>
    <message>
        <source>In use</source>
        <translation>In use</translation>
    </message>
    <message>
        <source>Life reached</source>
        <translation>Life reached</translation>
    </message>
    <message>
        <source>Selected, waits for the tool change</source>
        <translation>Selected, waits for the tool change</translation>
    </message>
    <message>
        <source>Waiting</source>
        <translation>Waiting</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>Count</translation>
    </message>
    <message>
        <source>Minutes</source>
        <translation>Minutes</translation>
    </message>
    <message>
        <source>In use: group %1 T%2</source>
        <translation>In use: group %1 T%2</translation>
    </message>
    <message>
        <source>In use: none</source>
        <translation>In use: none</translation>
    </message>
    <message>
        <source>Ignore No. %1</source>
        <translation>Ignore No. %1</translation>
    </message>
    <message>
        <source>Capacity: %1 groups x %2 tools</source>
        <translation>Capacity: %1 groups x %2 tools</translation>
    </message>
    <message>
        <source>No tool life groups. Enter them in a program or MDI: G10 L3, then P&lt;group&gt; L&lt;life&gt; Q&lt;1 count | 2 minutes&gt; and T&lt;tool&gt; H&lt;h&gt; D&lt;d&gt; blocks, then G11. They are kept in toollife.txt.</source>
        <translation>No tool life groups. Enter them in a program or MDI: G10 L3, then P&lt;group&gt; L&lt;life&gt; Q&lt;1 count | 2 minutes&gt; and T&lt;tool&gt; H&lt;h&gt; D&lt;d&gt; blocks, then G11. They are kept in toollife.txt.</translation>
    </message>
    <message>
        <source>Every tool has reached its life in group %1: selecting it is an alarm.</source>
        <translation>Every tool has reached its life in group %1: selecting it is an alarm.</translation>
    </message>
    <message>
        <source>toollife.txt: %1 line(s) could not be read; they are kept in the file as comments.</source>
        <translation>toollife.txt: %1 line(s) could not be read; they are kept in the file as comments.</translation>
    </message>
    <message>
        <source>toollife.txt not saved: %1</source>
        <translation>toollife.txt not saved: %1</translation>
    </message>
    <message>
        <source>Reset the tool life of group %1: every tool's used life back to 0?</source>
        <translation>Reset the tool life of group %1: every tool's used life back to 0?</translation>
    </message>
</context>
<context>
    <name>m350::ui::ToolTablePage</name>
    <message>
        <source>Tool Table</source>
        <translation>Tool Table</translation>
    </message>
    <message>
        <source>Flat end mill</source>
        <translation>Flat end mill</translation>
    </message>
    <message>
        <source>Ball nose</source>
        <translation>Ball nose</translation>
    </message>
    <message>
        <source>Bull nose</source>
        <translation>Bull nose</translation>
    </message>
    <message>
        <source>Drill</source>
        <translation>Drill</translation>
    </message>
    <message>
        <source>Tap</source>
        <translation>Tap</translation>
    </message>
    <message>
        <source>Chamfer</source>
        <translation>Chamfer</translation>
    </message>
    <message>
        <source>Engraver</source>
        <translation>Engraver</translation>
    </message>
    <message>
        <source>Face mill</source>
        <translation>Face mill</translation>
    </message>
    <message>
        <source>Reamer</source>
        <translation>Reamer</translation>
    </message>
    <message>
        <source>Touch probe</source>
        <translation>Touch probe</translation>
    </message>
    <message>
        <source>Other</source>
        <translation>Other</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Tool</translation>
    </message>
    <message>
        <source>Pocket</source>
        <translation>Pocket</translation>
    </message>
    <message>
        <source>Z offset</source>
        <translation>Z offset</translation>
    </message>
    <message>
        <source>Diameter</source>
        <translation>Diameter</translation>
    </message>
    <message>
        <source>Max rpm</source>
        <translation>Max rpm</translation>
    </message>
    <message>
        <source>Teeth</source>
        <translation>Teeth</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Comment</translation>
    </message>
    <message>
        <source>UP/DOWN: tool, LEFT/RIGHT: field, ENTER: edit. Touch Off: with the tool loaded and its tip on a known height, enter that work Z; the tool's Z offset changes so the display reads it.</source>
        <translation>UP/DOWN: tool, LEFT/RIGHT: field, ENTER: edit. Touch Off: with the tool loaded and its tip on a known height, enter that work Z; the tool's Z offset changes so the display reads it.</translation>
    </message>
    <message>
        <source>The table is the machine folder's tool.tbl in LinuxCNC's format; rpm, teeth and type are kept in the comment as {rpm=... teeth=... type=...}.</source>
        <translation>The table is the machine folder's tool.tbl in LinuxCNC's format; rpm, teeth and type are kept in the comment as {rpm=... teeth=... type=...}.</translation>
    </message>
    <message>
        <source>Modify</source>
        <translation>Modify</translation>
    </message>
    <message>
        <source>The table is empty</source>
        <translation>The table is empty</translation>
    </message>
    <message>
        <source>New</source>
        <comment>msg 328</comment>
        <translation>New</translation>
    </message>
    <message>
        <source>Del</source>
        <comment>msg 325</comment>
        <translation>Del</translation>
    </message>
    <message>
        <source>Touch Off</source>
        <translation>Touch Off</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Import</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Export</translation>
    </message>
    <message>
        <source>Tool Life</source>
        <translation>Tool Life</translation>
    </message>
    <message>
        <source>Breakage Monitor</source>
        <translation>Breakage Monitor</translation>
    </message>
    <message>
        <source>Cur Tool:</source>
        <comment>msg 992</comment>
        <translation>Cur Tool:</translation>
    </message>
    <message>
        <source>%1 tools</source>
        <translation>%1 tools</translation>
    </message>
    <message>
        <source>tool.tbl not saved: %1</source>
        <translation>tool.tbl not saved: %1</translation>
    </message>
    <message>
        <source>A tool keeps its number: add the new number with New and delete this one</source>
        <translation>A tool keeps its number: add the new number with New and delete this one</translation>
    </message>
    <message>
        <source>empty: none</source>
        <translation>empty: none</translation>
    </message>
    <message>
        <source>not a valid value</source>
        <translation>not a valid value</translation>
    </message>
    <message>
        <source>T%1: %2</source>
        <translation>T%1: %2</translation>
    </message>
    <message>
        <source>New tool number:</source>
        <translation>New tool number:</translation>
    </message>
    <message>
        <source>Tool numbers start at 1</source>
        <translation>Tool numbers start at 1</translation>
    </message>
    <message>
        <source>T%1 is already in the table</source>
        <translation>T%1 is already in the table</translation>
    </message>
    <message>
        <source>The tool table is full (1000 tools)</source>
        <translation>The tool table is full (1000 tools)</translation>
    </message>
    <message>
        <source>Delete T%1 from the tool table?</source>
        <translation>Delete T%1 from the tool table?</translation>
    </message>
    <message>
        <source>The current tool No. is 0, this operation is invalid!</source>
        <comment>msg 858</comment>
        <translation>The current tool No. is 0, this operation is invalid!</translation>
    </message>
    <message>
        <source>Touch off T%1: the work Z of its tip (gauge or cut surface):</source>
        <translation>Touch off T%1: the work Z of its tip (gauge or cut surface):</translation>
    </message>
    <message>
        <source>Not a number: %1</source>
        <translation>Not a number: %1</translation>
    </message>
    <message>
        <source>Import a tool.tbl (path; relative to the machine folder):</source>
        <translation>Import a tool.tbl (path; relative to the machine folder):</translation>
    </message>
    <message>
        <source>Replace the tool table with the %1 tools of %2?</source>
        <translation>Replace the tool table with the %1 tools of %2?</translation>
    </message>
    <message>
        <source>%1 lines skipped, the first: %2</source>
        <translation>%1 lines skipped, the first: %2</translation>
    </message>
    <message>
        <source>Tool table imported from %1</source>
        <translation>Tool table imported from %1</translation>
    </message>
    <message>
        <source>Export the tool table to (path; relative to the machine folder):</source>
        <translation>Export the tool table to (path; relative to the machine folder):</translation>
    </message>
    <message>
        <source>%1 is the loaded program: refused, nothing was written</source>
        <translation>%1 is the loaded program: refused, nothing was written</translation>
    </message>
    <message>
        <source>File save failed!</source>
        <comment>msg 907</comment>
        <translation>File save failed!</translation>
    </message>
    <message>
        <source>Tool table exported to %1</source>
        <translation>Tool table exported to %1</translation>
    </message>
</context>
<context>
    <name>m350::ui::TrainingStartPage</name>
    <message>
        <source>Training: %1</source>
        <translation>Training: %1</translation>
    </message>
    <message>
        <source>Exercise</source>
        <translation>Exercise</translation>
    </message>
    <message>
        <source>Level</source>
        <translation>Level</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Best time</source>
        <translation>Best time</translation>
    </message>
    <message>
        <source>not tried</source>
        <translation>not tried</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>passed</translation>
    </message>
    <message>
        <source>failed (%1 tries)</source>
        <translation>failed (%1 tries)</translation>
    </message>
</context>
<context>
    <name>m350::ui::TrainingWindow</name>
    <message>
        <source>The exam names exercise %1, which is not in %2</source>
        <translation>The exam names exercise %1, which is not in %2</translation>
    </message>
    <message>
        <source>Training</source>
        <translation>Training</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Open</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Back</translation>
    </message>
    <message>
        <source>Panel</source>
        <translation>Panel</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Task</source>
        <translation>Task</translation>
    </message>
    <message>
        <source>No hints (exam)</source>
        <translation>No hints (exam)</translation>
    </message>
    <message>
        <source>Hint</source>
        <translation>Hint</translation>
    </message>
    <message>
        <source>Hand in</source>
        <translation>Hand in</translation>
    </message>
    <message>
        <source>No more hints for this exercise.</source>
        <translation>No more hints for this exercise.</translation>
    </message>
    <message>
        <source>Hint %1: %2</source>
        <translation>Hint %1: %2</translation>
    </message>
</context>
<context>
    <name>m350::ui::UserAccess</name>
    <message>
        <source>Guest</source>
        <comment>msg 942</comment>
        <translation>Guest</translation>
    </message>
    <message>
        <source>Operator</source>
        <comment>msg 943</comment>
        <translation>Operator</translation>
    </message>
    <message>
        <source>Admin</source>
        <comment>msg 944</comment>
        <translation>Admin</translation>
    </message>
    <message>
        <source>Super</source>
        <comment>msg 945</comment>
        <translation>Super</translation>
    </message>
    <message>
        <source>Rights is limited,pls shift user's rights:</source>
        <comment>msg 934</comment>
        <translation>Rights is limited,pls shift user's rights:</translation>
    </message>
    <message>
        <source>The No. of characters &lt; 6,pls input again!</source>
        <comment>msg 918</comment>
        <translation>The No. of characters &lt; 6,pls input again!</translation>
    </message>
    <message>
        <source>File save failed!</source>
        <comment>msg 907</comment>
        <translation>File save failed!</translation>
    </message>
</context>
<context>
    <name>m350::ui::VerdictPage</name>
    <message>
        <source>PASSED: %1</source>
        <translation>PASSED: %1</translation>
    </message>
    <message>
        <source>FAILED: %1</source>
        <translation>FAILED: %1</translation>
    </message>
    <message>
        <source>score %1/100, time %2, hints %3</source>
        <translation>score %1/100, time %2, hints %3</translation>
    </message>
    <message>
        <source>time out</source>
        <translation>time out</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>Check</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Result</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Measured</translation>
    </message>
    <message>
        <source>Expected</source>
        <translation>Expected</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>passed</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>failed</translation>
    </message>
    <message>
        <source>parameter %1</source>
        <translation>parameter %1</translation>
    </message>
    <message>
        <source>output OUT%1</source>
        <translation>output OUT%1</translation>
    </message>
    <message>
        <source>tool T%1</source>
        <translation>tool T%1</translation>
    </message>
    <message>
        <source>This check passed.</source>
        <translation>This check passed.</translation>
    </message>
    <message>
        <source>F5 opens %1 in the panel.</source>
        <translation>F5 opens %1 in the panel.</translation>
    </message>
</context>
<context>
    <name>m350::ui::AttemptFile</name>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1: cannot read: %2</translation>
    </message>
    <message>
        <source>a line after the hand-in: the attempt ended on the line before</source>
        <translation>a line after the hand-in: the attempt ended on the line before</translation>
    </message>
    <message>
        <source>the line's hash does not follow the chain: the attempt was changed after it was recorded (or belongs to another exercise or exam)</source>
        <translation>the line's hash does not follow the chain: the attempt was changed after it was recorded (or belongs to another exercise or exam)</translation>
    </message>
    <message>
        <source>the line has no hash while the lines before it have: the attempt was changed after it was recorded</source>
        <translation>the line has no hash while the lines before it have: the attempt was changed after it was recorded</translation>
    </message>
    <message>
        <source>"attempt" names the exercise and the trainee on the first line only</source>
        <translation>"attempt" names the exercise and the trainee on the first line only</translation>
    </message>
    <message>
        <source>the hand-in's t must be a time not before the last action's (%1)</source>
        <translation>the hand-in's t must be a time not before the last action's (%1)</translation>
    </message>
</context>
<context>
    <name>m350::ui::AttemptGrader</name>
    <message>
        <source>--verdict %1 is the attempt it grades: refused, nothing written</source>
        <translation>--verdict %1 is the attempt it grades: refused, nothing written</translation>
    </message>
    <message>
        <source>--verdict %1 lies in the exercise folder %2: refused, nothing written</source>
        <translation>--verdict %1 lies in the exercise folder %2: refused, nothing written</translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1: cannot read: %2</translation>
    </message>
    <message>
        <source>%1: the attempt carries no hash chain: an exam takes only attempts the panel recorded in the exam</source>
        <translation>%1: the attempt carries no hash chain: an exam takes only attempts the panel recorded in the exam</translation>
    </message>
    <message>
        <source>%1:1: the attempt is at exercise "%2", not "%3"</source>
        <translation>%1:1: the attempt is at exercise "%2", not "%3"</translation>
    </message>
</context>
<context>
    <name>m350::ui::ClassReport</name>
    <message>
        <source>%1: no exercise "%2" in %3</source>
        <translation>%1: no exercise "%2" in %3</translation>
    </message>
</context>
<context>
    <name>m350::ui::CustomKeysPage</name>
    <message>
        <source>FUNC K01</source>
        <comment>msg 150</comment>
        <translation>FUNC K01</translation>
    </message>
    <message>
        <source>FUNC K02</source>
        <comment>msg 151</comment>
        <translation>FUNC K02</translation>
    </message>
    <message>
        <source>FUNC K03</source>
        <comment>msg 152</comment>
        <translation>FUNC K03</translation>
    </message>
    <message>
        <source>FUNC K04</source>
        <comment>msg 153</comment>
        <translation>FUNC K04</translation>
    </message>
    <message>
        <source>FUNC K05</source>
        <comment>msg 154</comment>
        <translation>FUNC K05</translation>
    </message>
    <message>
        <source>FUNC K06</source>
        <comment>msg 155</comment>
        <translation>FUNC K06</translation>
    </message>
    <message>
        <source>FUNC K07</source>
        <comment>msg 156</comment>
        <translation>FUNC K07</translation>
    </message>
    <message>
        <source>FUNC K08</source>
        <comment>msg 157</comment>
        <translation>FUNC K08</translation>
    </message>
    <message>
        <source>FUNC K09</source>
        <comment>msg 158</comment>
        <translation>FUNC K09</translation>
    </message>
    <message>
        <source>FUNC K10</source>
        <comment>msg 159</comment>
        <translation>FUNC K10</translation>
    </message>
    <message>
        <source>FUNC K11</source>
        <comment>msg 160</comment>
        <translation>FUNC K11</translation>
    </message>
    <message>
        <source>FUNC K12</source>
        <comment>msg 161</comment>
        <translation>FUNC K12</translation>
    </message>
    <message>
        <source>FUNC K13</source>
        <comment>msg 162</comment>
        <translation>FUNC K13</translation>
    </message>
    <message>
        <source>FUNC K14</source>
        <comment>msg 163</comment>
        <translation>FUNC K14</translation>
    </message>
</context>
<context>
    <name>m350::ui::ExternalOutputFile</name>
    <message>
        <source>File save failed!</source>
        <comment>msg 907</comment>
        <translation>File save failed!</translation>
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
</context>
<context>
    <name>m350::ui::OperatorAction</name>
    <message>
        <source>"t" (virtual time in seconds, &gt;= 0) is missing or not a number</source>
        <translation>"t" (virtual time in seconds, &gt;= 0) is missing or not a number</translation>
    </message>
    <message>
        <source>one action per line: found %1 besides "t"</source>
        <translation>one action per line: found %1 besides "t"</translation>
    </message>
    <message>
        <source>unknown key "%1"</source>
        <translation>unknown key "%1"</translation>
    </message>
    <message>
        <source>softkey must be 1-6 (F1-F6) or 7-12 (second row)</source>
        <translation>softkey must be 1-6 (F1-F6) or 7-12 (second row)</translation>
    </message>
    <message>
        <source>unknown page "%1" (one of: %2)</source>
        <translation>unknown page "%1" (one of: %2)</translation>
    </message>
    <message>
        <source>lang must be zh_CN or en</source>
        <translation>lang must be zh_CN or en</translation>
    </message>
    <message>
        <source>wheel axis must be X, Y, Z, A or B</source>
        <translation>wheel axis must be X, Y, Z, A or B</translation>
    </message>
    <message>
        <source>wheel step must be 1, 10 or 100</source>
        <translation>wheel step must be 1, 10 or 100</translation>
    </message>
    <message>
        <source>wheel seconds must be &gt;= 0</source>
        <translation>wheel seconds must be &gt;= 0</translation>
    </message>
    <message>
        <source>force input must be 1-24 (IN01-IN24)</source>
        <translation>force input must be 1-24 (IN01-IN24)</translation>
    </message>
    <message>
        <source>force fault must be stuck, slow, bouncing, pressed or none</source>
        <translation>force fault must be stuck, slow, bouncing, pressed or none</translation>
    </message>
    <message>
        <source>force level must be 0 or 1</source>
        <translation>force level must be 0 or 1</translation>
    </message>
    <message>
        <source>unknown action "%1" (one of: key, key_down, key_up, softkey, text, wheel, page, force, lang, load)</source>
        <translation>unknown action "%1" (one of: key, key_down, key_up, softkey, text, wheel, page, force, lang, load)</translation>
    </message>
</context>
<context>
    <name>m350::ui::Replay</name>
    <message>
        <source>a line holds one action, a JSON object {...}</source>
        <translation>a line holds one action, a JSON object {...}</translation>
    </message>
    <message>
        <source>'%1' closes nothing that is open</source>
        <translation>'%1' closes nothing that is open</translation>
    </message>
    <message>
        <source>text after the action's closing }: one action a line</source>
        <translation>text after the action's closing }: one action a line</translation>
    </message>
    <message>
        <source>unterminated string: the " opened here is not closed on this line</source>
        <translation>unterminated string: the " opened here is not closed on this line</translation>
    </message>
    <message>
        <source>missing '%1' at the end of the line (the '%2' at column %3 is not closed)</source>
        <translation>missing '%1' at the end of the line (the '%2' at column %3 is not closed)</translation>
    </message>
    <message>
        <source>expected {...}</source>
        <translation>expected {...}</translation>
    </message>
    <message>
        <source>t = %1 s is beyond the longest replay, %2 s (24 h) of virtual time</source>
        <translation>t = %1 s is beyond the longest replay, %2 s (24 h) of virtual time</translation>
    </message>
    <message>
        <source>t = %1 comes before the previous action's %2 (actions must be in time order)</source>
        <translation>t = %1 comes before the previous action's %2 (actions must be in time order)</translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1: cannot read: %2</translation>
    </message>
    <message>
        <source>%1:%2:%3: load "%4": a replay loads only a program the Program page shows on its disks (%5), links followed: refused</source>
        <translation>%1:%2:%3: load "%4": a replay loads only a program the Program page shows on its disks (%5), links followed: refused</translation>
    </message>
</context>
</TS>