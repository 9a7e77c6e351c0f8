// Filter kernels k of the hybrid LIC [W §4, eq. 5]: u in [-1, 1] along the streamline
// (0 at the seed, k(0) = 1). Box, exponential (IBFV-like, one-sided decay made symmetric),
// Gaussian (sigma = 1/3), Hann. KERNEL (a program define) picks one.
//   box          1
//   exponential  exp(-3 |u|)
//   Gaussian     exp(-4.5 u^2)
//   Hann         0.5 + 0.5 cos(pi u)
// The particle loop samples them at u = i du, i = 1, 2, ...; the walk below gives those
// weights by recurrence, one or two multiplies a step instead of an exp or a cos:
// exponential: times exp(-3 du) a step; Gaussian: times exp(-4.5 du^2 (2i - 1)), a ratio
// that itself shrinks by exp(-9 du^2) a step; Hann: (cos, sin) of pi u turned by pi du.
// Rounding drift (float32): below 2e-6 of k(0) up to L = 81, 3e-4 for the Gaussian at L = 1001.
struct KernelWalk {
    float weight;  // k(i du)
    float ratio;   // exponential, Gaussian: k((i + 1) du) / k(i du)
    float shrink;  // Gaussian: change of that ratio per step
    vec2 turn;     // Hann: (cos, sin) of pi du
    vec2 phase;    // Hann: (cos, sin) of pi i du
};
KernelWalk kernelWalk(float du) {
    KernelWalk w;
    w.weight = 1.0;
    w.ratio = KERNEL == KERNEL_EXPONENTIAL ? exp(-3.0 * du) : exp(-4.5 * du * du);
    w.shrink = exp(-9.0 * du * du);
    w.turn = vec2(cos(3.14159265 * du), sin(3.14159265 * du));
    w.phase = vec2(1.0, 0.0);
    return w;
}
// Advances the walk by one step: w.weight becomes k((i + 1) du).
void kernelNext(inout KernelWalk w) {
    if (KERNEL == KERNEL_EXPONENTIAL) {
        w.weight *= w.ratio;
    } else if (KERNEL == KERNEL_GAUSSIAN) {
        w.weight *= w.ratio;
        w.ratio *= w.shrink;
    } else if (KERNEL == KERNEL_HANN) {
        w.phase = vec2(w.phase.x * w.turn.x - w.phase.y * w.turn.y, w.phase.y * w.turn.x + w.phase.x * w.turn.y);
        w.weight = 0.5 + 0.5 * w.phase.x;
    }
}
#ifdef ORIENTED
// Oriented LIC [Wegenkittl, Groller, Purgathofer 1997]: the kernel made one-sided, so that a
// sparse drop smears into a streak that brightens downstream and ends in a sharp head. v in
// [0, 1] runs along the streamline from its backward end (v = 0) to its forward end: the
// chosen kernel's half from its peak outward, stretched over the whole filter length. A
// pixel the drop reaches at the backward end of its streamline lies downstream of it and
// gets the most weight. (Box has no falloff: refused by the caller.)
//   exponential  exp(-3 v)      Gaussian  exp(-4.5 v^2)      Hann  0.5 + 0.5 cos(pi v)
float orientedWeight(float v) {
    if (KERNEL == KERNEL_EXPONENTIAL) return exp(-3.0 * v);
    if (KERNEL == KERNEL_HANN) return 0.5 + 0.5 * cos(3.14159265 * v);
    return exp(-4.5 * v * v);
}
#endif
