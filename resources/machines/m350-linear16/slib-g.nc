// slib-g.nc of the default machine: G-code handlers (O9000+n) and the T-code tool change O20000.
// Written for M350 Studio after the M350 manual's chapter "刀库定制详解" (fixed linear rack,
// side loading). Repairs to the manual's printed listing, whose PDF extraction lost characters:
//  - indirect references regain their '#[': WHILE [#[1520+#13-1] NE 0], #[1552+#20-1] = 1,
//    G53 X#[1330+#1300-1] (the X of the current tool's pocket, not #1330 plus a tool number)
//  - the exits GOTO4 land on an N4 that the listing lacked
//  - the spindle is stopped (M05) before waiting for its stopped signal, as step 2 of the flow says

O20000(换刀程序 T-code tool change)
IF #1>[#1301] GOTO4                 //target above the magazine capacity: nothing to do
IF #1300==#1 GOTO4                  //target already in the spindle
(判断XYZ是否回过参考点 are X Y Z homed?)
IF [#1515+#1516+#1517]>=3 GOTO50    //all homed: go on at N50
#1503 = 1(X,Y,Z轴机械未全部归零!)
G04 P10
GOTO4
N50
IF#1300 != 0 GOTO56                 //spindle tool 0: the operator must load a tool by hand
#1503 = 1(当前刀具号不能为0,请手动装一把刀!)
G04 P100
GOTO4
N56
IF #1!= 0 GOTO57                    //target 0 is not a tool
#1503 = 1(目标刀具号不能为0! )
G04 P100
GOTO4
N57
#20= 1                              //clamp/release output OUT01
#11= 11                             //tool released input IN11 (1 = released)
#12= 11                             //tool clamped: the same IN11 back at 0
#13= 7                              //spindle stopped input IN07 (0 = stopped)
M05                                 //stop the spindle
WHILE [#[1520+#13-1] NE 0] DO1      //wait for IN07 = 0
G04 P10
END1
G53 Z#1306 F#1312                   //Z up to the change height (param 806) at param 812
G53 Y#1309 F#1311                   //to the Y pre-point (param 809)
G53 X#[1330+#1300-1] F#1311         //to the X of the current tool's pocket
G53 Z#1307 F#1312                   //down to the change height (param 807)
G53 Y#[1350+#1300-1] F#1313         //slide the tool into its fork (param 813)
#[1552+#20-1] = 1                   //release (松刀)
G04 P200
WHILE [#[1520+#11-1] NE 1] DO2      //wait for IN11 = 1
G04 P10
END2
G53 Z#1306 F#1312                   //up, leaving the tool in its pocket
G53 X#[1330+#1-1] Y#[1350+#1-1] F#1311 //above the target tool
G53 Z[#1307+40] F#1312              //quickly to 40 mm above the change height
G53 Z#1307 F#1313                   //slowly onto the tool
#[1552+#20-1] = 0                   //clamp (紧刀)
G04 P200
WHILE [#[1520+#12-1] NE 0] DO3      //wait for IN11 = 0
G04 P10
END3
G53 Y#1309 F#1313                   //slide the tool out of its fork to the pre-point
G53 Z#1306 F#1312                   //Z up
N5
#1300 = #1                          //the target is now the current tool: work Z uses its offset
#1503 = 1000                        //clear the status line
M99
N4
M99                                 //exits keep their message on the status line
