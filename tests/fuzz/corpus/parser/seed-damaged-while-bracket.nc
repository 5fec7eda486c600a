(the manual's damaged listing lost '#[' before the indirect reference)
#13= 7                              //spindle stopped input IN07
M05
WHILE [#1520+#13-1] NE 0] DO1      //wait for IN07 = 0
G04 P10
END1
M30
