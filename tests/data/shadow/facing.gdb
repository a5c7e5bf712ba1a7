# facing.gdb: trace --shadow-history tests. The FACE normal, not the winding, says
# which way a facet faces (gdb(5)). Facet 1-1-1 is wound clockwise seen from above but
# its normal points up; facet 1-1-2 is wound counter-clockwise seen from above but
# its normal points down. Units: metres; material 1 (grass).
OBJECT
plates
1-0-0
PART
plates
1-1-0
FACE
clockwise, facing up
1-1-1
grass
1
plates
-1
5
-1
-1
null
null
null
4
0 0 0
0 10 0
10 10 0
10 0 0
0 0 1
0
0
null
FACE
counter-clockwise, facing down
1-1-2
grass
1
plates
-1
5
-1
-1
null
null
null
4
20 0 0
30 0 0
30 10 0
20 10 0
0 0 -1
180
0
null
END
