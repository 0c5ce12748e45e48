# Log-log SVG plot of RMS error against wall time from a bench/sweep.sh CSV:
# one curve per method (points joined in time order), decade ticks with
# unlabelled 2..9 minor ticks, a legend, and the reference's noise floor dashed.
#   awk -v title=T -v floor=F -f bench/plot_svg.awk sweep.csv > plot.svg
# Plain POSIX awk so it runs wherever the sweep does (no plotting package).
function lg(v) { return log(v) / log(10) }
function px(t) { return L + (lg(t) - x0) / (x1 - x0) * W }
function py(e) { return T + H - (lg(e) - y0) / (y1 - y0) * H }
function fmt(e) { return e >= 1 ? sprintf("%d", e + 0.5) : sprintf("%g", e) }
BEGIN { FS = "\""; L = 70; T = 40; W = 520; H = 360; R = 210; B = 50 }
NR > 1 {
    split($1, a, ","); split($3, b, ",")
    m = a[1]; e = b[3] + 0; t = b[6] + 0
    if (e < 1e-5) e = 1e-5          # exact answers: drawn at the bottom
    if (t < 1e-3) t = 1e-3
    if (!(m in count)) { order[++nm] = m }
    k = ++count[m]; tx[m, k] = t; ey[m, k] = e
    if (n == 0 || t < tmin) tmin = t; if (n == 0 || t > tmax) tmax = t
    if (n == 0 || e < emin) emin = e; if (n == 0 || e > emax) emax = e
    n++
}
END {
    if (floor + 0 > 0 && floor + 0 < emin) emin = floor + 0
    x0 = int(lg(tmin) + 100) - 100; x1 = -int(-lg(tmax) + 100) + 100; if (x1 <= x0) x1 = x0 + 1
    y0 = int(lg(emin) + 100) - 100; y1 = -int(-lg(emax) + 100) + 100; if (y1 <= y0) y1 = y0 + 1
    split("#1f77b4 #d62728 #2ca02c #ff7f0e #9467bd #8c564b #e377c2 #17becf #7f7f7f #bcbd22", pal, " ")
    printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" font-size=\"12\">\n", L + W + R, T + H + B
    printf "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n"
    printf "<text x=\"%d\" y=\"22\" font-size=\"14\" font-weight=\"bold\">%s</text>\n", L, title
    # grid and ticks
    for (d = x0; d <= x1; d++) for (s = 1; s <= 9; s++) {
        v = d + lg(s); if (v > x1 + 1e-9) break
        x = L + (v - x0) / (x1 - x0) * W
        printf "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"%s\"/>\n", x, T, x, T + H, s == 1 ? "#ccc" : "#eee"
        if (s == 1) printf "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%s</text>\n", x, T + H + 16, fmt(10 ^ d)
    }
    for (d = y0; d <= y1; d++) for (s = 1; s <= 9; s++) {
        v = d + lg(s); if (v > y1 + 1e-9) break
        y = T + H - (v - y0) / (y1 - y0) * H
        printf "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"%s\"/>\n", L, y, L + W, y, s == 1 ? "#ccc" : "#eee"
        if (s == 1) printf "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%s</text>\n", L - 6, y + 4, fmt(10 ^ d)
    }
    printf "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" stroke=\"black\"/>\n", L, T, W, H
    printf "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">wall time (s, minimum of the runs)</text>\n", L + W / 2, T + H + 38
    printf "<text transform=\"translate(18,%d) rotate(-90)\" text-anchor=\"middle\">RMS relative error (%%)</text>\n", T + H / 2
    if (floor + 0 > 0) {
        y = py(floor + 0)
        printf "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#888\" stroke-dasharray=\"6,4\"/>\n", L, y, L + W, y
        printf "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\" fill=\"#666\">reference noise %s %%</text>\n", L + W - 4, y - 4, floor
    }
    # curves: points of each method joined in order of time
    for (i = 1; i <= nm; i++) {
        m = order[i]; c = pal[(i - 1) % 10 + 1]; k = count[m]
        for (p = 1; p <= k; p++) { st[p] = tx[m, p]; se[p] = ey[m, p] }
        for (p = 2; p <= k; p++) for (q = p; q > 1 && st[q] < st[q - 1]; q--) {
            v = st[q]; st[q] = st[q - 1]; st[q - 1] = v; v = se[q]; se[q] = se[q - 1]; se[q - 1] = v }
        pts = ""
        for (p = 1; p <= k; p++) pts = pts sprintf("%.1f,%.1f ", px(st[p]), py(se[p]))
        printf "<polyline points=\"%s\" fill=\"none\" stroke=\"%s\" stroke-width=\"1.8\"/>\n", pts, c
        for (p = 1; p <= k; p++) printf "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.2\" fill=\"%s\"/>\n", px(st[p]), py(se[p]), c
        ly = T + 10 + 20 * i
        printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"%s\" stroke-width=\"2\"/>\n", L + W + 12, ly, L + W + 34, ly, c
        printf "<circle cx=\"%d\" cy=\"%d\" r=\"3.2\" fill=\"%s\"/>\n", L + W + 23, ly, c
        printf "<text x=\"%d\" y=\"%d\">%s</text>\n", L + W + 40, ly + 4, m
    }
    print "</svg>"
}
