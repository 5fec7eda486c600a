1(writing #3000 raises macro alarm 3000 + n with the comment as its message)
#100 = 1
IF [#100 EQ 1] GOTO 9
M30
N9 #3000 = 1 (TOOL BROKEN)
#100 = 2
M30
