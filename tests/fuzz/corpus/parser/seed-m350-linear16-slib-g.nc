// slib-g.nc of the default machine: G-code handlers (O9000+n) and the T-code tool change O20000.
// Written for M350 Studio after the M350 manual's chapter "刀库定制详解" (fixed linear rack,
// side loading). Repairs to the manual's printed listing, whose PDF extraction lost characters:
//  - indirect references regain their '#[': WHILE [#[1520+#13-1] NE 0], #[1552+#20-1] = 1,
//    G53 X#[1330+#1300-1] (the X of the current tool's pocket, not #1330 plus a tool number)
//  - the exits GOTO4 land on an N4 that the listing lacked
//  - the spindle is stopped (M05) before waiting for its stopped signal, as step 2 of the flow says

O20000(换刀程序 T-code tool change)
IF #1>[#1301+20*#1303] GOTO4        //above the magazine (and, with param 803, the virtual tools)
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
#2 = #880                           //where the change began (param 815 returns there)
#3 = #881
#20= 1                              //clamp/release output OUT01
#11= 11                             //tool released input IN11 (1 = released)
#12= 11                             //tool clamped: the same IN11 back at 0
#13= 7                              //spindle stopped input IN07 (0 = stopped)
M05                                 //stop the spindle
WHILE [#[1520+#13-1] NE 0] DO1      //wait for IN07 = 0
G04 P10
END1
IF #1300 > #1301 GOTO70             //a virtual tool in the spindle: the operator takes it out
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
N71 IF #1 > #1301 GOTO72            //a virtual target: the operator puts it in
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
IF #1305 == 0 GOTO6                 //param 805: set the new tool on the fixed setter
#1502 = 2
M98 P502
N6 IF #1315 == 0 GOTO7              //param 815: back to where the change began
G53 Z#1306 F#1312
G53 X#2 Y#3 F#1311
N7 #1503 = 1000                     //clear the status line
M99
N70 M98 P20001 X#1300 Y0            //out by hand at the manual change place
IF #50 < 0 GOTO4
GOTO71
N72 M98 P20001 X#1 Y1               //in by hand
IF #50 GE 0 GOTO5
#1300 = 0                           //no START key: the spindle stays empty, its tool went home
GOTO4
N4
M99                                 //exits keep their message on the status line

O20001(虚拟刀 a virtual tool changed by hand: X#1 the tool, Y#2 0 take it out, 1 put it in)
// Written for M350 Studio after the firmware's flow: to the manual change place (params 816-818),
// a prompt, then the extern START key (params 599-601) pressed and let go. #50 says how it went:
// 0 done, -1 no START key wired.
#50 = 0
G53 Z#1318 F#1312
G53 X#1316 Y#1317 F#1311
#1510 = #1
IF #2 == 1 GOTO1
M154                                //release: the operator takes the tool out
M301
#1503 = 1(请取下虚拟刀[T%.0f]后,按外部启动键!)
GOTO2
N1 #1503 = 1(请手动更换虚拟刀号[T%.0f]后,按外部启动键进行自动对刀!)
N2 IF [#1100 == 0] + [#1099 < 1] GOTO9
WHILE [#[1520+#1099-1] NE #1101] DO1 //wait for START
G04 P10
END1
WHILE [#[1520+#1099-1] EQ #1101] DO2 //and for its release
G04 P10
END2
IF #2 == 0 GOTO3
M155                                //clamp the tool the operator put in
M302
N3 M99
N9 #50 = -1
#1503 = 1(外部启动键未设置! extern START, params 599-601, is not set)
M99

// Canned drilling cycles (钻孔循环), as M350 handler programs O9000+n, written for M350 Studio.
// The controller calls the handler for the cycle's first block and again for each later block that
// names a new hole or level, until G80 or G00-G03. Each call gets, in work coordinates:
//   #0 #1 X Y of the hole   #2 Z the bottom   #10 R level   #14 Q peck   #13 P dwell (ms)
//   #16 F feed   #9 K repeats (1 if not given)   #30 the Z to return to (G98: initial, G99: R)
//   #31 the Z the tool stands at   #32 1 on the cycle's first block (a tool below R goes up first)
// Param 224 (#724) is the G73/G83 clearance d; 0 means 0.254 mm.

O9081(G81 钻孔循环 drilling: feed to Z, rapid out)
IF [#32 EQ 0] + [#31 GE #10] GOTO1  //starting below R: straight up to R first
G00 Z#10
N1 G00 X#0 Y#1                      //to the hole at the current level
#20 = 0
WHILE [#20 LT #9] DO1               //K times
G00 Z#10
G01 Z#2 F#16
G00 Z#30
#20 = #20 + 1
END1
M99

O9082(G82 钻孔循环 drilling with a dwell at the bottom)
IF [#32 EQ 0] + [#31 GE #10] GOTO1
G00 Z#10
N1 G00 X#0 Y#1
#20 = 0
WHILE [#20 LT #9] DO1
G00 Z#10
G01 Z#2 F#16
IF #13 LE 0 GOTO2
G04 P#13                            //dwell at the bottom
N2G00 Z#30
#20 = #20 + 1
END1
M99

O9083(G83 深孔钻循环 peck drilling: out to R after every peck)
IF [#32 EQ 0] + [#31 GE #10] GOTO1
G00 Z#10
N1 G00 X#0 Y#1
#21 = #724                          //clearance d above the depth already drilled
IF #21 GT 0 GOTO2
#21 = 0.254
N2 #20 = 0
WHILE [#20 LT #9] DO1
G00 Z#10
#22 = #10                           //depth drilled so far
WHILE [#22 GT #2] DO2
#23 = #22 - #14                     //the next peck
IF #23 GE #2 GOTO3
#23 = #2
N3 IF #22 GE #10 GOTO4              //the first peck starts at R
G00 Z[#22 + #21]                    //back down, d above the bottom so far
N4 G01 Z#23 F#16
IF #23 LE #2 GOTO5                  //at the bottom: straight to the return level
G00 Z#10                            //out to R: the chips come out
N5 #22 = #23
END2
G00 Z#30
#20 = #20 + 1
END1
M99

O9073(G73 高速深孔钻循环 high-speed peck drilling: back off d after every peck)
IF [#32 EQ 0] + [#31 GE #10] GOTO1
G00 Z#10
N1 G00 X#0 Y#1
#21 = #724
IF #21 GT 0 GOTO2
#21 = 0.254
N2 #20 = 0
WHILE [#20 LT #9] DO1
G00 Z#10
#22 = #10
WHILE [#22 GT #2] DO2
#23 = #22 - #14
IF #23 GE #2 GOTO3
#23 = #2
N3 G01 Z#23 F#16
IF #23 LE #2 GOTO4                  //at the bottom: no back-off
G00 Z[#23 + #21]                    //break the chip
N4 #22 = #23
END2
G00 Z#30
#20 = #20 + 1
END1
M99

O9084(G84 攻丝循环 right-hand tapping: the spindle turns forward going in)
IF [#32 EQ 0] + [#31 GE #10] GOTO1
G00 Z#10
N1 G00 X#0 Y#1
#20 = 0
WHILE [#20 LT #9] DO1
G00 Z#10
G01 Z#2 F#16
IF #13 LE 0 GOTO2
G04 P#13
N2 M04                              //reverse to come out
G01 Z#10 F#16
M03                                 //forward again
G00 Z#30
#20 = #20 + 1
END1
M99

O9074(G74 反攻丝循环 left-hand tapping: the spindle turns in reverse going in)
IF [#32 EQ 0] + [#31 GE #10] GOTO1
G00 Z#10
N1 G00 X#0 Y#1
#20 = 0
WHILE [#20 LT #9] DO1
G00 Z#10
G01 Z#2 F#16
IF #13 LE 0 GOTO2
G04 P#13
N2 M03                              //forward to come out
G01 Z#10 F#16
M04                                 //reverse again
G00 Z#30
#20 = #20 + 1
END1
M99
