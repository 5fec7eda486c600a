// slib-g.nc of the top-loading rack machine: O20000, the T-code tool change, in the factory flow
// for a fixed row (magazine type 3) whose forks are loaded from above. Written for M350 Studio.
// The actuators and sensor waits are the M codes of slib-m.nc (M154/M155 release/clamp,
// M300-M302 spindle stopped / released / clamped), each on the port of its parameter triple.

O20000(换刀程序 T-code tool change: fixed row, top loading)
IF #1>[#1301] GOTO4                 //target above the magazine capacity: nothing to do
IF #1300==#1 GOTO4                  //target already in the spindle
IF [#1515+#1516+#1517]>=3 GOTO50    //X Y Z homed: go on
#1503 = 1(X,Y,Z轴机械未全部归零!)
G04 P10
GOTO4
N50 IF #1300 != 0 GOTO56
#1503 = 1(当前刀具号不能为0,请手动装一把刀!)
G04 P100
GOTO4
N56 IF #1 != 0 GOTO57
#1503 = 1(目标刀具号不能为0! )
G04 P100
GOTO4
N57 M155                            //safe state: clamped
M05                                 //stop the spindle
M300                                //and wait until it has
G53 Z#1306 F#1312                   //up to the change height
G53 X#[1330+#1300-1] Y#[1350+#1300-1] F#1311 //over the current tool's fork
G53 Z#[1370+#1300-1] F#1312         //down: the tool into its fork
M154                                //release (松刀)
G04 P100
M301                                //wait: released
G53 Z#1306 F#1312                   //up, the tool stays in its fork
G53 X#[1330+#1-1] Y#[1350+#1-1] F#1311 //over the target tool
G53 Z#[1370+#1-1] F#1312            //down onto it
M155                                //clamp (紧刀)
G04 P200
M302                                //wait: clamped
G53 Z#1306 F#1312                   //up with the new tool
#1300 = #1                          //the current tool: work Z uses its offset
IF [#1305 == 0] + [#1300 == 0] GOTO6  //param 805: set the new tool on the fixed setter
#1502 = 2
M98 P502
N6 #1503 = 1000
M99
N4 M99
