# degenerate.gdb: trace tests; box_on_plane.gdb with the box top's four vertices
# made one point (a zero-area facet with repeated vertices, 2-1-1).
OBJECT
ground
1-0-0
PART
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
20 0 0
20 20 0
0 20 0
0 0 1
0
0
null
OBJECT
box
2-0-0
PART
house side
2-1-0
FACE
top
2-1-1
wood
37
house side
-1
5
-1
-1
null
null
null
4
8 8 3
8 8 3
8 8 3
8 8 3
0 0 1
0
0
null
FACE
south wall
2-1-2
wood
37
house side
-1
5
-1
-1
null
null
null
4
8 8 0
12 8 0
12 8 3
8 8 3
0 -1 0
90
180
null
FACE
east wall
2-1-3
wood
37
house side
-1
5
-1
-1
null
null
null
4
12 8 0
12 12 0
12 12 3
12 8 3
1 0 0
90
90
null
FACE
north wall
2-1-4
wood
37
house side
-1
5
-1
-1
null
null
null
4
12 12 0
8 12 0
8 12 3
12 12 3
0 1 0
90
0
null
FACE
west wall
2-1-5
wood
37
house side
-1
5
-1
-1
null
null
null
4
8 12 0
8 8 0
8 8 3
8 12 3
-1 0 0
90
270
null
END
