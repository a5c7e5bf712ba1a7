OBJECT
ground
1-0-0
PARTS
lawn
1-1-0
FACE
lawn top
1-1-1
grass
1
lawn
-1
5
-1
-1
null
null
null
4
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
0
0
null
END
