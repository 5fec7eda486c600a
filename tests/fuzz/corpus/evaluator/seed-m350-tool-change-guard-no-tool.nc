0(spindle tool 0: O20000 asks the operator to load a tool by hand)
T2
M30
