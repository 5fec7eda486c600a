(FANUC ATAN[a]/[b] answers 0 to 360 degrees)
#1 = ATAN[1]/[1]
#2 = ATAN[-1]/[-1]
#3 = ATAN[1]/[-1]
#4 = ATAN[0]/[-1]
#5 = ATAN[-1]/[0]
#6 = ATAN[1,-1]
M30
