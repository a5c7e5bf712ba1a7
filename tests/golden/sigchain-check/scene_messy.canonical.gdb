OBJECT
marker post
3-0-0
PART
post
3-1-0
FACE
post face
3-1-1
paint, white
12
post
-1
5
-1
-1
null
null
null
3
0 0 0
1 0 0
0 1 0
0 0 1
0
0
null
END
