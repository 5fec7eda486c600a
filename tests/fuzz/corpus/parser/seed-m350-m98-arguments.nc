(M98 passes X Y Z as #1 #2 #3 and opens a new local level on the M350; L repeats)
#1=99
M98 P100 X5 Y6 Z7
#100=#1
M98 P200 L3
M30
O100
#101=#1
#102=#2
#103=#3
#104=#1+#2+#3
M99
O200
#110=#110+1
M99
