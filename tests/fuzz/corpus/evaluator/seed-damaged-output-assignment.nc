0(the manual's damaged release line: '#[' lost before 1552)
#20= 1
#1552+#20-1] = 1                   //release (松刀)
G04 P200
M30
