(M99 P<n> returns to label n of the caller)
M98 P500
#100=1       //skipped
N7 #101=1
M30
O500
#102=1
M99 P7
