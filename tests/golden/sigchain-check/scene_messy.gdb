# Input for the .gdb --rewrite golden: comments, blank lines, indentation and number
# spellings that the canonical form normalises. One triangle.
OBJECT
   marker post       # names are whole lines, trimmed
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
5.0
-1
-1
null
null
null
3
 0.0   0.0  0.0
 1e0,  0,   0       # commas separate too
 0     1.0  0
0 0 +1
0.0
0
null
END
