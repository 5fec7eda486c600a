(#1510-#1513 fill the %.Nf placeholders of #1503 and #1505 texts)
#1510=5
#1511=2.5
#1512=-0.125
#1503=1(T[%.0f] length %.3f, 100%% done)
#1503=1(%.1f %.2f)
#1503=1000(cleared: not shown)
#1505=1(Change to T%.0f?)
#100=#1505
M30
