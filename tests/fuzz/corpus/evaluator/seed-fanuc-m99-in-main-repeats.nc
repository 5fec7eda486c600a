1(FANUC: M99 in the main program goes back to its start; here until #100 reaches 3)
#100 = #100 + 1
IF [#100 GE 3] GOTO 9
M99
N9 M30
