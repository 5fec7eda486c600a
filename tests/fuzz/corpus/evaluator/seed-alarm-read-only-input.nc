0(inputs IN01-IN24 are #1520-#1543 and read-only)
#100=#1520
#1520=1
M30
