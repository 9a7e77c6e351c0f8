// ISA edge detection, [L] eq. 14: an edge advection point is where
// |z_{k-1} - z_k| > eps * |p'_{k-1} - p'_k|, with z the linear depth normalised to the
// depth range (near..far) and p' in pixels. A texture coordinate that lands on the
// background is an edge too (inflow from the background).
float linearDepth01(float windowDepth, float nearP, float farP, bool ortho) {
    float zEye = ortho ? nearP + windowDepth * (farP - nearP)
                       : nearP * farP / (farP - windowDepth * (farP - nearP));
    return (zEye - nearP) / (farP - nearP);
}
float edgeFlag(float depthK, float depthPrev, vec2 pK, vec2 pPrev, float eps, float nearP, float farP,
               bool ortho) {
    if (depthPrev >= 1.0) return 1.0;
    float zK = linearDepth01(depthK, nearP, farP, ortho);
    float zPrev = linearDepth01(depthPrev, nearP, farP, ortho);
    // A floor of one pixel keeps slow regions from flagging depth noise as edges.
    return abs(zPrev - zK) > eps * max(length(pPrev - pK), 1.0) ? 1.0 : 0.0;
}
