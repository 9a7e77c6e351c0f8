// Filter kernels k of the hybrid LIC [W §4, eq. 5]: u in [-1, 1] along the streamline
// (0 at the seed). Box, exponential (IBFV-like, one-sided decay made symmetric),
// Gaussian (sigma = 1/3), Hann.
float kernelWeight(int kernel, float u) {
    float a = abs(u);
    if (kernel == KERNEL_BOX) return 1.0;
    if (kernel == KERNEL_EXPONENTIAL) return exp(-3.0 * a);
    if (kernel == KERNEL_GAUSSIAN) return exp(-4.5 * a * a);
    return 0.5 + 0.5 * cos(3.14159265 * a);
}
