0(a machine folder's slib-g.nc handles G100 as O9100 with X -> #0, Y -> #1)
G100 X2 Y3
M30
