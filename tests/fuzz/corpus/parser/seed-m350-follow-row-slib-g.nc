// slib-g.nc of the follow-row machine: O20000, the T-code tool change, in the factory flow for a
// rack carried on the gantry (magazine type 2). Written for M350 Studio. The rack rides with the
// spindle in Y, so only X positions a pocket; the slide (M152 out / M153 in, sensors M303/M304)
// carries the forks onto the tool in the spindle and away.

O20000(换刀程序 T-code tool change: follow row on the gantry)
IF #1>[#1301] GOTO4                 //target above the magazine capacity: nothing to do
IF #1300==#1 GOTO4                  //target already in the spindle
IF [#1515+#1516+#1517]>=3 GOTO50    //X Y Z homed: go on
#1503 = 1(X,Y,Z轴机械未全部归零!)
G04 P10
GOTO4
N50 IF #1300 == 0 GOTO60            //an empty spindle: straight to loading
M05                                 //unload: stop the spindle
G53 Z#1306 F#1312                   //up to the change height
G53 X#[1330+#1300-1] F#1311         //to the current tool's fork (X only: the rack rides along)
G53 Z#[1370+#1300-1] F#1319         //down to fork height, the slide still in
M300                                //the spindle has stopped
M152                                //slide out: the fork takes the tool
M303
M154                                //release
M301
#1300 = 0
G53 Z#1306 F#1312                   //up, the tool stays in its fork
IF #1 != 0 GOTO60
M153                                //T0: nothing to load, slide in
M304
GOTO4
N60 IF #1 == 0 GOTO4
G53 Z#1306 F#1312                   //load
M300
M154                                //an empty nose comes down released
M301
G53 X#[1330+#1-1] F#1311            //over the target tool
M152                                //slide out (already out after an unload)
M303
G53 Z[#[1370+#1-1]+10] F#1319       //down close
G53 Z#[1370+#1-1] F1000             //and onto the tool slowly
M155                                //clamp
G04 P#1314
M302
#1300 = #1                          //the current tool: work Z uses its offset
M153                                //slide in: the fork leaves the tool
M304
G53 Z#1306 F#1312
IF [#1305 == 0] + [#1300 == 0] GOTO6  //param 805: set the new tool on the fixed setter
#1502 = 2
M98 P502
N6 #1503 = 1000
N4 M99
