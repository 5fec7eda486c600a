// The tool change the panel asks for (written for M350 Studio): #1504 holds the target tool; the
// T word runs the machine's O20000.
T#1504
