0(OUT01 drives IN11 150 ms later on the default machine; outputs stay as left)
#1552=1
#100=#1530   //IN11 right after the release: still 0
G04 P200
#101=#1530   //200 ms later: 1
#102=#1552
#1556=1      //OUT05
M30
