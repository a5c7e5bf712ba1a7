# nofit_ocean.awk: the sea mask from the DEM alone (README.md, "No fit at all"). Input: the
# DEM as gdal_translate -of XYZ writes it (x y height, row by row). Output: an ESRI ASCII
# grid on the DEM's grid, 1 where the cell is at sea level (height <= 0) and no cell within
# RADIUS cells (Chebyshev distance: RADIUS x 90 m in x and y) is above 0, else 0.
# Usage: awk -v radius=2 -v cols=111 -v rows=111 -v x0=.. -v y0=.. -v cell=.. -f nofit_ocean.awk
{ h[int((NR - 1) / cols), (NR - 1) % cols] = $3 }
END {
    printf "ncols %d\nnrows %d\nxllcorner %.6f\nyllcorner %.6f\ncellsize %.9f\n", \
        cols, rows, x0, y0 - rows * cell, cell
    for (r = 0; r < rows; r++) {
        line = ""
        for (c = 0; c < cols; c++) {
            sea = h[r, c] <= 0
            for (i = r - radius; sea && i <= r + radius; i++)
                for (j = c - radius; sea && j <= c + radius; j++)
                    if (i >= 0 && i < rows && j >= 0 && j < cols && h[i, j] > 0) sea = 0
            line = line (c ? " " : "") sea
        }
        print line
    }
}
