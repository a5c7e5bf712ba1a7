# tower.gdb: the 100 x 100 plane of plane_100m.gdb with a 10 x 10 x 50 box at its
# centre (x and y from 45 to 55, top at z = 50; a top and four walls, concrete,
# material 2). Test scene for find_min_max_view_angle.
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
100 0 0
100 100 0
0 100 0
0 0 1
0
0
null
OBJECT
tower
2-0-0
PART
tower
2-1-0
FACE
top
2-1-1
concrete
2
tower
-1
5
-1
-1
null
null
null
4
45 45 50
55 45 50
55 55 50
45 55 50
0 0 1
0
0
null
FACE
south wall
2-1-2
concrete
2
tower
-1
5
-1
-1
null
null
null
4
45 45 0
55 45 0
55 45 50
45 45 50
0 -1 0
90
180
null
FACE
east wall
2-1-3
concrete
2
tower
-1
5
-1
-1
null
null
null
4
55 45 0
55 55 0
55 55 50
55 45 50
1 0 0
90
90
null
FACE
north wall
2-1-4
concrete
2
tower
-1
5
-1
-1
null
null
null
4
55 55 0
45 55 0
45 55 50
55 55 50
0 1 0
90
0
null
FACE
west wall
2-1-5
concrete
2
tower
-1
5
-1
-1
null
null
null
4
45 55 0
45 45 0
45 45 50
45 55 50
-1 0 0
90
270
null
END
