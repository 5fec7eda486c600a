1(bitwise AND OR XOR, MOD; AND binds like *, OR and XOR like +)
#1 = 12 AND 10
#2 = 12 OR 3
#3 = 12 XOR 10
#4 = 17 MOD 5
#5 = 2 + 12 AND 10
#6 = 1 OR 2 * 3
IF [[#1 EQ 8] AND [#2 EQ 15]] THEN #7 = 1
IF [[#1 EQ 9] OR [#2 EQ 15]] THEN #8 = 1
IF [[#1 EQ 9] OR [#2 EQ 16]] THEN #9 = 1
M30
