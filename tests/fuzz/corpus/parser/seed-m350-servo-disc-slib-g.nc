// slib-g.nc of the servo disc machine: O20000, the T-code tool change for magazine type 4 (圆盘),
// which the stock M350 macro leaves unimplemented, and O20004, which turns the disc. Written for
// M350 Studio. Pocket k holds tool k. The disc turns only with Z up at param 806, clear of it; at
// the station (params 808/809) a tool goes down into its cup to Z param 807 and an empty spindle
// comes down onto the next one.

O20000(换刀程序 T-code tool change: servo disc)
IF #1>#1301 GOTO4                   //target above the disc's pockets: nothing to do
IF #1300==#1 GOTO4                  //target already in the spindle
IF [#1515+#1516+#1517]>=3 GOTO50    //X Y Z homed: go on
#1503 = 1(X,Y,Z轴机械未全部归零!)
G04 P10
GOTO4
N50 #2 = #880                       //where the change began (param 815 returns there)
#3 = #881
M05                                 //stop the spindle
M300                                //and wait until it has
G53 Z#1306 F#1312                   //up, clear of the disc
IF #1300 == 0 GOTO60                //an empty spindle: straight to fetching
M98 P20004 X#1300                   //the current tool's own pocket to the station
G53 X#1308 Y#1309 F#1311            //over the station
G53 Z[#1307+40] F#1312              //quickly to 40 mm above the cup
G53 Z#1307 F#1313                   //slowly down: the tool into its cup
M154                                //release (松刀)
M301
G53 Z#1306 F#1312                   //up, the tool stays in its cup
#1300 = 0
N60 IF #1 == 0 GOTO5                //T0: put away only
M98 P20004 X#1                      //the target's pocket to the station
G53 X#1308 Y#1309 F#1311
M154                                //an empty nose comes down released
M301
G53 Z[#1307+40] F#1312
G53 Z#1307 F#1313                   //onto the tool
M155                                //clamp (紧刀)
G04 P#1314
M302
G53 Z#1306 F#1312                   //up with the new tool
N5 #1300 = #1                       //the current tool: work Z uses its offset
IF [#1305 == 0] + [#1300 == 0] GOTO6  //param 805: set the new tool on the fixed setter
#1502 = 2
M98 P502
N6 IF #1315 == 0 GOTO7                 //param 815: back to where the change began
G53 X#2 Y#3 F#1311
N7 #1503 = 1000
N4 M99

O20004(圆盘转位 turn the servo disc: X#1 the pocket to bring to the station)
// The drive takes the pocket number in binary on OUT05-OUT08 (bit 0 on OUT05), starts on a pulse
// on OUT09 and says it is in position on IN13.
#10 = 5                             //first position-select output
#11 = 4                             //how many
#12 = 9                             //start (strobe) output
#13 = 13                            //in-position input
#5 = #1
#6 = 0
WHILE [#6 LT #11] DO1               //the pocket number, bit by bit
#[1552+#10+#6-1] = #5 - 2*FIX[#5/2]
#5 = FIX[#5/2]
#6 = #6 + 1
END1
#[1552+#12-1] = 1                   //start
G04 P50
#[1552+#12-1] = 0
WHILE [#[1520+#13-1] NE 1] DO2      //wait until the disc stands in position
G04 P10
END2
M99
