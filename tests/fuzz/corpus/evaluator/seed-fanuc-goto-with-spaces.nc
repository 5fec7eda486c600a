1(FANUC ignores spaces: GO TO 10 is GOTO10)
#1 = 1
GO TO 10
#100 = 1
N10 #101 = 1
IF [#1 EQ 1] GO TO 20
#102 = 1
N20 #103 = 1
G O T O 30
#104 = 1
N 30 M30
