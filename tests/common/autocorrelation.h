// flowsurf tests — the streak length the GL and the viewer tests measure: the lag (pixels)
// along (dx, dy) at which the normalised autocorrelation of value(x, y) over the box
// [x0, x1) x [y0, y1) falls below 0.5, linearly interpolated between lags; `maxLag` when it
// does not. `inBox`: pairs whose second pixel leaves the box are skipped; otherwise it is
// read wherever it lies (the caller keeps the box maxLag pixels inside the image).
#pragma once

#include <cstddef>

namespace flowsurf::test {

template <class Value>
float autocorrelationLength(const Value& value, int x0, int y0, int x1, int y1, int dx, int dy, int maxLag,
                            bool inBox) {
    double sum = 0, sum2 = 0;
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const double v = value(x, y);
            sum += v;
            sum2 += v * v;
            ++n;
        }
    const double mean = sum / n, var = sum2 / n - mean * mean;
    double prev = 1.0;
    for (int lag = 1; lag < maxLag; ++lag) {
        double c = 0;
        int m = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                const int xs = x + lag * dx, ys = y + lag * dy;
                if (inBox && (xs < x0 || xs >= x1 || ys < y0 || ys >= y1)) continue;
                c += (value(x, y) - mean) * (value(xs, ys) - mean);
                ++m;
            }
        if (m == 0) return float(lag);
        const double rho = c / m / var;
        if (rho < 0.5) return float(lag - 1) + float((prev - 0.5) / (prev - rho));  // linear crossing
        prev = rho;
    }
    return float(maxLag);
}

}  // namespace flowsurf::test
