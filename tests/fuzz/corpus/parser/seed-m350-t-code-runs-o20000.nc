(T2 on the default machine: O20000 in slib-g.nc changes tool 1 for tool 2)
T2
M30
