(G65 on the M350: A -> #4, B -> #5, I -> #7; the callee's locals are its own)
#1=11
#10=12
G65 P300 A1 B2 I3
#100=#1
#101=#10
M30
O300
#102=#4
#103=#5
#104=#7
#105=#10
#1=50
M99
