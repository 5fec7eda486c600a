(a loop that never ends is stopped by the simulated-time limit)
#100=0
WHILE [1==1] DO1
#100=#100+1
G04 P100
END1
M30
