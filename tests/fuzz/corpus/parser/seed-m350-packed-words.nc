(words written without spaces, as panels save them)
G90G01X10.5Y-20F500
G91X1Y1
G90
#1=2#2=3
G00X#1Y[#2*2]Z-1.
M30
