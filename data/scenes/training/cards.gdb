# cards.gdb: the two-gray-card calibration scene (White (1996), section 4.2.4), hand-written
# for sigchain; metres. A 20 x 20 m dark plane (material 100, reflectance
# 0.05) at z = 0 and two flat 4 x 4 m cards 1 cm above it, in the middle of the view
# of cards.adv: card 1 (dark gray, reflectance 0.2, material 101) at x 4..8 and
# card 2 (light gray, reflectance 0.6, material 102) at x 12..16, both y 8..12.
OBJECT
plane
1-0-0
PART
dark plane
1-1-0
FACE
plane top
1-1-1
dark
100
dark plane
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
cards
2-0-0
PART
card 1
2-1-0
FACE
card 1
2-1-1
gray20
101
card 1
-1
5
-1
-1
null
null
null
4
4 8 0.01
8 8 0.01
8 12 0.01
4 12 0.01
0 0 1
0
0
null
PART
card 2
2-2-0
FACE
card 2
2-2-1
gray60
102
card 2
-1
5
-1
-1
null
null
null
4
12 8 0.01
16 8 0.01
16 12 0.01
12 12 0.01
0 0 1
0
0
null
END
