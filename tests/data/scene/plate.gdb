# plate.gdb: a 1 x 1 quad at z = 0 (material 3, 2 cm, 25 C) and a triangle beside it
# (material 4, thickness and temperature from the material). Test scene for
# tests/unit/scene.
OBJECT
plate
1-0-0
PART
top
1-1-0
FACE
square
1-1-1
metal
3
plate
25
2
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
FACE
wedge
1-1-2
paint
4
plate
-1
-1
-1
-1
null
null
null
3
2 0 0
3 0 0
2 1 0
0 0 1
0
0
null
END
