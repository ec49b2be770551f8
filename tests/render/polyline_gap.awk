# The largest distance from a point of the first polyline to the second polyline (piecewise linear),
# over the points of the first: `awk -f polyline_gap.awk A.json B.json` on two `bentray trace`
# outputs. Prints "N points, gap G, ends E" where E is the distance between the two last points.
function seg_dist(px, py, pz, ax, ay, az, bx, by, bz,    dx, dy, dz, l2, t, cx, cy, cz) {
    dx = bx - ax; dy = by - ay; dz = bz - az; l2 = dx * dx + dy * dy + dz * dz
    t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy + (pz - az) * dz) / l2 : 0
    t = t < 0 ? 0 : t > 1 ? 1 : t
    cx = ax + t * dx - px; cy = ay + t * dy - py; cz = az + t * dz - pz
    return sqrt(cx * cx + cy * cy + cz * cz)
}
FNR == 1 { file++ }
/^    \[/ {
    gsub(/[\[\],]/, " "); split($0, v, " ")
    if (file == 1) { n1++; x1[n1] = v[1]; y1[n1] = v[2]; z1[n1] = v[3] }
    else { n2++; x2[n2] = v[1]; y2[n2] = v[2]; z2[n2] = v[3] }
}
END {
    gap = 0
    for (i = 1; i <= n1; i++) {
        best = -1
        for (j = 1; j < n2; j++) {
            d = seg_dist(x1[i], y1[i], z1[i], x2[j], y2[j], z2[j], x2[j + 1], y2[j + 1], z2[j + 1])
            if (best < 0 || d < best) best = d
        }
        if (best > gap) gap = best
    }
    ex = x1[n1] - x2[n2]; ey = y1[n1] - y2[n2]; ez = z1[n1] - z2[n2]
    printf "%d points, gap %.2g, ends %.2g\n", n1, gap, sqrt(ex * ex + ey * ey + ez * ez)
}
