(the manual's listing jumps to GOTO4 without an N4)
M98 P1000 X20
M30
O1000
IF #1>[#1301] GOTO4    //target above the capacity
#100=1
M99
