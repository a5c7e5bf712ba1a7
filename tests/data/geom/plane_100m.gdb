# plane_100m.gdb: one horizontal 100 x 100 square, x and y from 0 to 100 at z = 0,
# as one quad (grass, material 1). Test scene for find_min_max_view_angle.
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
END
