0(IN11 held at 0: the tool is never reported released and the T2 change waits forever)
T2
M30
