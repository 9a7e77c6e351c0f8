#include "methods/skeleton_layer/skeleton_layer.h"

#include "gpu/shader_interface.h"

#include <vector>

namespace flowsurf::methods {

namespace {

// Uniform arrays of the style tables, and the near/far planes the depth test compares in.
void setCommon(const gl::Program& p, const gl::Texture2D& target, const core::Camera& camera) {
    const float aspect = float(target.width()) / float(target.height());
    const glm::mat4 vp = camera.viewProjection(aspect);
    glProgramUniformMatrix4fv(p.id(), p.uniform("viewProj"), 1, GL_FALSE, &vp[0][0]);
    glProgramUniform2f(p.id(), p.uniform("viewportPx"), float(target.width()), float(target.height()));
    glProgramUniform3f(p.id(), p.uniform("depthPlanes"), camera.nearPlane, camera.farPlane,
                       camera.orthoHeight > 0.0f ? 1.0f : 0.0f);
}

}  // namespace

SkeletonLayer::SkeletonLayer()
    : lines_(program({{GL_VERTEX_SHADER, "skeleton_layer/lines.vert"}, {GL_FRAGMENT_SHADER, "skeleton_layer/lines.frag"}})),
      points_(program({{GL_VERTEX_SHADER, "skeleton_layer/points.vert"},
                       {GL_FRAGMENT_SHADER, "skeleton_layer/points.frag"}})),
      vao_(gl::VertexArray::create()),
      fbo_(gl::Framebuffer::create()) {
    std::vector<glm::vec3> lineColours(kLineColours.begin(), kLineColours.end());
    glProgramUniform3fv(lines_.id(), lines_.uniform("kindColour"), GLsizei(lineColours.size()), &lineColours[0].x);
    std::vector<glm::vec3> colours;
    std::vector<int> shapes;
    for (const GlyphStyle& s : kPointStyles) {
        colours.push_back(s.colour);
        shapes.push_back(s.shape);
    }
    glProgramUniform3fv(points_.id(), points_.uniform("typeColour"), GLsizei(colours.size()), &colours[0].x);
    glProgramUniform1iv(points_.id(), points_.uniform("typeShape"), GLsizei(shapes.size()), shapes.data());
}

void SkeletonLayer::upload(const skeleton::Skeleton& s) {
    polylines_ = s.lines;
    piecesUploaded_ = 0;
    for (const skeleton::SkeletonLine& l : s.lines) piecesUploaded_ += l.points.size() > 1 ? l.points.size() - 1 : 0;
    std::vector<glm::vec4> pts;
    for (const skeleton::CriticalPoint& p : s.criticalPoints) pts.emplace_back(p.position, float(p.type));
    pointCount_ = GLsizei(pts.size());
    // two triangles over a piece's four corners (a -, b -, b +, a +): each corner shaded once;
    // enough for every piece, a view draws the first of them
    std::vector<GLuint> corners;
    for (GLuint q = 0; q < GLuint(piecesUploaded_); ++q)
        for (GLuint c : {0u, 1u, 2u, 0u, 2u, 3u}) corners.push_back(4 * q + c);
    quadCorners_ = corners.empty() ? gl::Buffer() : gl::Buffer(GLsizeiptr(corners.size() * sizeof(GLuint)), corners.data());
    glVertexArrayElementBuffer(vao_.id(), quadCorners_.id());
    segments_ = gl::Buffer();
    segmentCount_ = 0;
    piecesCamera_.reset();
    pointBuffer_ = pts.empty() ? gl::Buffer() : gl::Buffer(GLsizeiptr(pts.size() * sizeof(glm::vec4)), pts.data());
}

void SkeletonLayer::simplifyFor(const core::Camera& camera, const core::Viewport& viewport, float reachPx) {
    if (piecesCamera_ && core::sameCamera(*piecesCamera_, camera) && piecesViewport_.width == viewport.width &&
        piecesViewport_.height == viewport.height && piecesReachPx_ == reachPx)
        return;  // a static camera: the pieces of the last frame
    SimplifyParams params;
    params.reachPx = reachPx;
    // per piece: the point before it (w 1 where there is one), a (w the kind), b, the point after
    std::vector<glm::vec4> seg;
    for (const ViewPiece& q : viewPieces(polylines_, camera, viewport, params)) {
        const skeleton::SkeletonLine& l = polylines_[q.line];
        seg.emplace_back(l.points[q.prev], q.prev != q.a ? 1.0f : 0.0f);
        seg.emplace_back(l.points[q.a], float(l.kind));
        seg.emplace_back(l.points[q.b], 0.0f);
        seg.emplace_back(l.points[q.next], q.next != q.b ? 1.0f : 0.0f);
    }
    segmentCount_ = GLsizei(seg.size() / 4);
    // a new store each view rather than a rewrite of the one the last frame may still read
    segments_ = seg.empty() ? gl::Buffer() : gl::Buffer(GLsizeiptr(seg.size() * sizeof(glm::vec4)), seg.data());
    piecesCamera_ = camera;
    piecesViewport_ = viewport;
    piecesReachPx_ = reachPx;
}

void SkeletonLayer::draw(const gl::Texture2D& composite, const gl::Texture2D& surfaceDepth, const core::Camera& camera,
                         const SkeletonStyle& style) {
    const float halfWidthPx = 0.5f * style.lineWidth + 1.0f;  // the outline's
    // a piece's quad reaches r = halfWidthPx + 1 beyond its ends (cap) and up to 2 r across (miter)
    if (style.lines && piecesUploaded_ > 0)
        simplifyFor(camera, {composite.width(), composite.height()}, 2.0f * (halfWidthPx + 1.0f) + 1.0f);
    if ((!style.lines || segmentCount_ == 0) && (!style.points || pointCount_ == 0)) return;
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, composite.id(), 0);
    glNamedFramebufferDrawBuffer(fbo_.id(), GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, composite.width(), composite.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glBindTextureUnit(bindings::kSkeletonDepth, surfaceDepth.id());
    glBindVertexArray(vao_.id());
    if (style.lines && segmentCount_ > 0) {
        setCommon(lines_, composite, camera);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kSkeletonSegments, segments_.id());
        lines_.use();
        // outline and core in one pass, premultiplied: the mitred pieces of a line do not overlap
        glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        glProgramUniform1f(lines_.id(), lines_.uniform("halfWidthPx"), halfWidthPx);
        glDrawElements(GL_TRIANGLES, 6 * segmentCount_, GL_UNSIGNED_INT, nullptr);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    }
    if (style.points && pointCount_ > 0) {
        setCommon(points_, composite, camera);
        glProgramUniform1f(points_.id(), points_.uniform("sizePx"), style.glyphSize);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kSkeletonPoints, pointBuffer_.id());
        points_.use();
        glDrawArraysInstanced(GL_TRIANGLES, 0, 6, pointCount_);
    }
    glDisable(GL_BLEND);
    glBindVertexArray(0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, 0, 0);
}

}  // namespace flowsurf::methods
