(with no axis homed, O20000 refuses to change tools)
T2
M30
