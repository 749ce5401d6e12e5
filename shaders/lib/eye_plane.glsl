// The radiosity pass clamps depth (MeshRenderer::drawRadiosityPass), which turns off near-plane
// clipping, and with it the only clipping of a surface's part behind the eye (w <= 0). Mesa's
// llvmpipe clips that part away regardless; an NVIDIA H200 rasterised a triangle running behind
// the camera over 62 % of the view where it should have covered all of it, at depths that hid
// nothing behind it. So every vertex stage clips at a plane just in front of the eye,
// w = nearestW (a hundredth of zNear), through user clip distance 0 (enabled with the clamp).
layout(std140, binding = 0) uniform EyePlane {
  float nearestW;
};

void clipBehindTheEye() { gl_ClipDistance[0] = gl_Position.w - nearestW; }
