# box_on_plane.gdb: the training scene of White (1996), section 4.2.1: "a box ... sitting
# on a flat surface". Hand-built for sigchain; White (1996) shows no .gdb sample.
# Units are not in the file (the .odb or the .adv `units` key gives them): metres here.
# Ground: a 20 x 20 quad at z = 0 (grass, material 1). Box: 4 x 4 x 3, x and y from
# 8 to 12, a top and four walls (wood, material 37, White (1996), table 4.2 defaults:
# temperature -1 (from therm), thickness 5 cm, power -1, exposed area -1).
# Vertices run counter-clockwise seen from the side the normal points to; slope
# zenith is the normal's angle from +z, slope azimuth its compass direction (deg
# clockwise from north, +y).
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
12 8 3
12 12 3
8 12 3
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
