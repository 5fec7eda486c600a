(a program that calls itself runs out of call levels)
M98 P100
M30
O100
#100=#100+1
M98 P100
M99
