// slib-g.nc of the multi-process machine: O20000, the T-code change for magazine type 1 (多工序),
// after the factory flow: stop the spindle, Z up, every head's cylinder closed (M169 M171 M173
// M175), then the cylinder of the head asked for opened (M168, M170, M172 or M174). Written for M350
// Studio.

O20000(换刀程序 T-code change: multi-process heads)
IF #1>#1301 GOTO4                   //no such head: nothing to do
IF #1300==#1 GOTO4                  //that head is already down
IF [#1515+#1516+#1517]>=3 GOTO50    //X Y Z homed: go on
#1503 = 1(X,Y,Z轴机械未全部归零!)
G04 P10
GOTO4
N50 M05                             //stop the spindle
M300
G53 Z#1306 F#1312                   //up: a head comes down only above the work
M169                                //every head up
M171
M173
M175
G04 P#1314
IF #1 == 0 GOTO5                    //T0: every head stays up
M[168+[#1-1]*2]                     //the head asked for, down
G04 P#1314
N5 #1300 = #1                       //work Z uses its offset
IF [#1305 == 0] + [#1300 == 0] GOTO6  //param 805: set the new tool on the fixed setter
#1502 = 2
M98 P502
N6 #1503 = 1000
N4 M99
