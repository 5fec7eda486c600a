// K1 (param 210 = 0 runs this file; written for M350 Studio): park. Z up to machine 0, then X and
// Y to the machine position after homing (params 122-123, #622-#623).
#1503 = 1(K1: 停靠 parking...)
G90 G53 G00 Z0
G53 G00 X#622 Y#623
#1503 = 1000
