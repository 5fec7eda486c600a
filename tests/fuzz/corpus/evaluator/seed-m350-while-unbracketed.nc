0(M350 conditions may go without brackets, as the factory macros write them)
#13=3
#100=0
WHILE#13>0DO13
#100=#100+#13
#13=#13-1
END13
IF#100 != 6 GOTO9
#101=1
N9
M30
