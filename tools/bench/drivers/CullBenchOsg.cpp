// The OpenSceneGraph side of `arcomp-bench cull`: the scene of CullScene.hpp
// as MatrixTransform → LOD → shared Geode per level, culled by
// osgUtil::CullVisitor the way osgUtil::SceneView::cullStage drives it.
// Compiled only where OpenSceneGraph was found.
#ifdef ARCOMP_HAVE_OSG

#include "tools/bench/drivers/CullBenchOsg.hpp"
#include "graph/core/Geometry.hpp"

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LOD>
#include <osg/MatrixTransform>
#include <osg/Viewport>
#include <osgUtil/CullVisitor>
#include <osgUtil/RenderStage>
#include <osgUtil/StateGraph>

#include <chrono>

namespace arcomp {

namespace {

// Our bounds are the spheres around the mesh; OSG's Geode would take the
// sphere around the box (radius √3 for a unit sphere). Both sides must cull
// the same spheres for their counts to agree.
struct FixedBound : osg::Node::ComputeBoundingSphereCallback {
    explicit FixedBound(const Sphere& s) : sphere(osg::Vec3(s.center.x, s.center.y, s.center.z), s.radius) {}
    osg::BoundingSphere computeBound(const osg::Node&) const override { return sphere; }
    osg::BoundingSphere sphere;
};

osg::ref_ptr<osg::Geode> makeLevel(const Geometry& g) {
    auto vertices = new osg::Vec3Array;
    auto normals = new osg::Vec3Array;
    for (std::size_t i = 0; i < g.positions.size(); ++i) {
        vertices->push_back({g.positions[i].x, g.positions[i].y, g.positions[i].z});
        normals->push_back({g.normals[i].x, g.normals[i].y, g.normals[i].z});
    }
    auto elements = new osg::DrawElementsUInt(GL_TRIANGLES, g.indices.begin(), g.indices.end());
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry;
    geometry->setVertexArray(vertices);
    geometry->setNormalArray(normals, osg::Array::BIND_PER_VERTEX);
    geometry->addPrimitiveSet(elements);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(geometry);
    geode->setComputeBoundingSphereCallback(new FixedBound(g.bound));
    return geode;
}

struct OsgScene {
    osg::ref_ptr<osg::Group> root = new osg::Group;
    osg::ref_ptr<osg::Geode> levels[3];
};

void addGroup(OsgScene& out, const CullScene& s, std::uint32_t group, osg::Group* parent) {
    const CullGroup& g = s.groups[group];
    for (std::uint32_t k : g.objects) {
        osg::ref_ptr<osg::MatrixTransform> t =
            new osg::MatrixTransform(osg::Matrix::translate(s.positions[k].x, s.positions[k].y, s.positions[k].z));
        osg::ref_ptr<osg::LOD> lod = new osg::LOD;
        lod->setRangeMode(osg::LOD::DISTANCE_FROM_EYE_POINT);
        lod->addChild(out.levels[0], 0.0f, kCullRanges[0]);
        lod->addChild(out.levels[1], kCullRanges[0], kCullRanges[1]);
        lod->addChild(out.levels[2], kCullRanges[1], std::numeric_limits<float>::max());
        t->addChild(lod);
        parent->addChild(t);
    }
    for (std::uint32_t child : g.groups) {
        osg::ref_ptr<osg::Group> sub = new osg::Group;
        parent->addChild(sub);
        addGroup(out, s, child, sub.get());
    }
}

CullFrameCounts countLeaves(osgUtil::RenderBin& bin, const OsgScene& scene) {
    CullFrameCounts counts;
    for (osgUtil::StateGraph* sg : bin.getStateGraphList())
        for (const auto& leaf : sg->_leaves) {
            ++counts.visible;
            for (int l = 0; l < 3; ++l)
                if (leaf->_drawable.get() == scene.levels[l]->getDrawable(0)) ++counts.levels[l];
        }
    for (const auto& [number, sub] : bin.getRenderBinList()) {
        const CullFrameCounts c = countLeaves(*sub, scene);
        counts.visible += c.visible;
        for (int l = 0; l < 3; ++l) counts.levels[l] += c.levels[l];
    }
    return counts;
}

}  // namespace

struct OsgCull::State {
    explicit State(const CullScene& s) : description(s) {}
    OsgScene scene;
    osg::ref_ptr<osgUtil::CullVisitor> cull = new osgUtil::CullVisitor;
    osg::ref_ptr<osgUtil::StateGraph> stateGraph = new osgUtil::StateGraph;
    osg::ref_ptr<osgUtil::RenderStage> stage = new osgUtil::RenderStage;
    osg::ref_ptr<osg::StateSet> localState = new osg::StateSet;
    osg::ref_ptr<osg::Viewport> viewport = new osg::Viewport(0, 0, kCullWidth, kCullHeight);
    osg::ref_ptr<osg::FrameStamp> frameStamp = new osg::FrameStamp;
    osg::Matrixd projection =
        osg::Matrixd::perspective(kCullFovyDegrees, double(kCullWidth) / kCullHeight, kCullNear, kCullFar);
    const CullScene& description;
    unsigned frameNumber = 0;
};

OsgCull::OsgCull(const CullScene& s) : state_(std::make_unique<State>(s)) {
    State& st = *state_;
    for (int l = 0; l < 3; ++l)
        st.scene.levels[l] = makeLevel(makeUvSphere(1.0f, kCullSphereSlices[l], kCullSphereStacks[l]));
    addGroup(st.scene, s, 0, st.scene.root.get());
    st.scene.root->getBound();  // bounds are computed lazily; not part of a frame
    // All six planes and no small-feature culling, as our select pass; near
    // and far are fixed, not computed from the scene.
    st.cull->setCullingMode(osg::CullSettings::VIEW_FRUSTUM_CULLING);
    st.cull->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
}

OsgCull::~OsgCull() {
    // Tearing the scene down would take longer than the benchmark: every
    // LOD leaves the parent list of the shared Geodes, one erase at a time,
    // which is quadratic in the object count. The process ends right after.
    State& st = *state_;
    st.stage->reset();
    st.stateGraph->clean();
    static_cast<void>(st.scene.root.release());
    for (auto& level : st.scene.levels) static_cast<void>(level.release());
}

std::pair<double, CullFrameCounts> OsgCull::frame(int frame, int frames) {
    State& st = *state_;
    const CullCamera c = cullCamera(st.description, frame, frames);
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(c.eye.x, c.eye.y, c.eye.z),
                                                   osg::Vec3d(c.target.x, c.target.y, c.target.z), osg::Vec3d(0, 1, 0));
    const auto start = std::chrono::steady_clock::now();
    // As SceneView::cullStage: reset, hand over the render graph, push
    // viewport and matrices, traverse, pop, sort and prune.
    st.frameStamp->setFrameNumber(st.frameNumber++);
    st.cull->reset();
    st.cull->setFrameStamp(st.frameStamp.get());
    st.cull->setTraversalNumber(st.frameStamp->getFrameNumber());
    st.stateGraph->clean();
    st.stage->reset();
    st.cull->setStateGraph(st.stateGraph.get());
    st.cull->setRenderStage(st.stage.get());
    st.stage->setViewport(st.viewport.get());
    st.stage->setInitialViewMatrix(new osg::RefMatrix(view));
    st.cull->pushStateSet(st.localState.get());
    st.cull->pushViewport(st.viewport.get());
    st.cull->pushProjectionMatrix(new osg::RefMatrix(st.projection));
    st.cull->pushModelViewMatrix(new osg::RefMatrix(view), osg::Transform::ABSOLUTE_RF);
    st.scene.root->accept(*st.cull);
    st.cull->popModelViewMatrix();
    st.cull->popProjectionMatrix();
    st.cull->popViewport();
    st.cull->popStateSet();
    st.stage->sort();
    st.stateGraph->prune();
    const auto stop = std::chrono::steady_clock::now();
    return {std::chrono::duration<double, std::milli>(stop - start).count(), countLeaves(*st.stage, st.scene)};
}

}  // namespace arcomp

#endif
