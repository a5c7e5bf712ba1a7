# training.gdb: the training scene of sigchain's pipeline tests (White (1996), section 4.2.1:
# "a box ... sitting on a flat surface"), here with a pyramid beside the box.
# Hand-written for sigchain; metres (the .adv's units key).
# Ground: a 20 x 20 m quad at z = 0 (grass, material 1).
# Box: 4 x 4 x 3 m, x 4..8, y 8..12, a top and four walls (wood, material 37).
# Pyramid: 4 x 4 m base, x 12..16, y 8..12, apex (14, 10, 4), four triangles (wood).
# Neither has a bottom face (it would lie on the ground, unseen).
# Facet fields as White (1996), table 4.2 defaults: temperature -1 (from therm),
# thickness 5 cm, power -1, exposed area -1. Vertices run counter-clockwise seen from
# the side the normal points to; slope zenith is the normal's angle from +z (a
# pyramid face's normal (0, -2, 1) has atan(2) = 63.4349488 deg), slope azimuth its
# compass direction (deg clockwise from north, +y).
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
box walls
2-1-0
FACE
top
2-1-1
wood
37
box walls
-1
5
-1
-1
null
null
null
4
4 8 3
8 8 3
8 12 3
4 12 3
0 0 1
0
0
null
FACE
south wall
2-1-2
wood
37
box walls
-1
5
-1
-1
null
null
null
4
4 8 0
8 8 0
8 8 3
4 8 3
0 -1 0
90
180
null
FACE
east wall
2-1-3
wood
37
box walls
-1
5
-1
-1
null
null
null
4
8 8 0
8 12 0
8 12 3
8 8 3
1 0 0
90
90
null
FACE
north wall
2-1-4
wood
37
box walls
-1
5
-1
-1
null
null
null
4
8 12 0
4 12 0
4 12 3
8 12 3
0 1 0
90
0
null
FACE
west wall
2-1-5
wood
37
box walls
-1
5
-1
-1
null
null
null
4
4 12 0
4 8 0
4 8 3
4 12 3
-1 0 0
90
270
null
OBJECT
pyramid
3-0-0
PART
pyramid faces
3-1-0
FACE
south face
3-1-1
wood
37
pyramid faces
-1
5
-1
-1
null
null
null
3
12 8 0
16 8 0
14 10 4
0 -2 1
63.4349488
180
null
FACE
east face
3-1-2
wood
37
pyramid faces
-1
5
-1
-1
null
null
null
3
16 8 0
16 12 0
14 10 4
2 0 1
63.4349488
90
null
FACE
north face
3-1-3
wood
37
pyramid faces
-1
5
-1
-1
null
null
null
3
16 12 0
12 12 0
14 10 4
0 2 1
63.4349488
0
null
FACE
west face
3-1-4
wood
37
pyramid faces
-1
5
-1
-1
null
null
null
3
12 12 0
12 8 0
14 10 4
-2 0 1
63.4349488
270
null
END
