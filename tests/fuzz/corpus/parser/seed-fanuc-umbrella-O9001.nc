(O9001: the umbrella carousel's tool change, called by M06, as the paper gives it:)
(張俊, 一種斗笠式刀庫換刀宏程序的設計. Return only for T0, fetch into an empty spindle, or)
(both. #1000 T already in the spindle, #1001 spindle tool is 0, #1002 T0 commanded.)
O9001
N10 IF[#1000EQ1]GO TO 290 (T代碼等於主軸刀號 T already in the spindle)
N20 #199=#4003 (G90/G91 MODLE)
N30 #198=#4006 (G20/G21 MODLE)
N40 #197=#4005 (G98/G99 MODLE)
N50 G91M19 (主軸準停 orient the spindle)
N60 IF[#1001EQ1]GO TO 220 (主軸上無刀則直接抓刀 empty spindle: fetch only)
N70 G91 G30 P3Z0 (Z軸移動到第三參考點 to the change height)
N80 M81 (刀庫準備好使能 magazine ready)
N90 M83 (刀庫向右靠近主軸 carousel to the spindle)
N100 G04 X0.5
N110 M11 (主軸松刀 release)
N120 G04 X0.5
N130 G91 G30 P2 Z0 (移動到第二參考點 up above the tools)
N140 IF[#1002EQ1]GO TO 180 (T0: nothing to fetch)
N150 M82 (刀盤旋轉 turn the carousel)
N160 G91 G30 P3 Z0 (Z軸移動到第三參考點 down onto the tool)
N170 G04 X0.5
N180 M10 (主軸夾緊刀具 clamp)
N190 M85 (存儲刀號 store the tool number)
N200 M84 (刀盤向左遠離主軸 carousel back)
N210 GO TO 280
N220 G91 G30 P2 Z0 (Z軸移動到第二參考點 up above the tools)
N230 M11 (主軸松刀 release)
N240 M82 (刀盤旋轉 turn the carousel)
N250 G04 X0.5
N260 M83 (刀庫向右靠近主軸 carousel to the spindle)
N270 GO TO 160
N280 G#199 G#198 G#197 (恢復模態 restore the modes)
N290 M99 (結束換刀程序)
