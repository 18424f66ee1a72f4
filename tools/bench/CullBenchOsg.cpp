// The OpenSceneGraph side of `arcomp bench cull`: the scene of CullScene.hpp
// as MatrixTransform → LOD → shared Geode per level, culled by
// osgUtil::CullVisitor the way osgUtil::SceneView::cullStage drives it.
// Compiled only where OpenSceneGraph was found.
#ifdef ARCOMP_HAVE_OSG

#include "graph/core/Geometry.hpp"
#include "tools/bench/CullScene.hpp"

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
        osg::ref_ptr<osg::MatrixTransform> t = new osg::MatrixTransform(
            osg::Matrix::translate(s.positions[k].x, s.positions[k].y, s.positions[k].z));
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

} // namespace

CullRun runOsgCull(const CullScene& s, int warmup, int frames) {
    OsgScene scene;
    for (int l = 0; l < 3; ++l) scene.levels[l] = makeLevel(makeUvSphere(1.0f, kCullSphereSlices[l], kCullSphereStacks[l]));
    addGroup(scene, s, 0, scene.root.get());
    scene.root->getBound();  // bounds are computed lazily; not part of a frame

    osg::ref_ptr<osgUtil::CullVisitor> cull = new osgUtil::CullVisitor;
    osg::ref_ptr<osgUtil::StateGraph> stateGraph = new osgUtil::StateGraph;
    osg::ref_ptr<osgUtil::RenderStage> stage = new osgUtil::RenderStage;
    osg::ref_ptr<osg::StateSet> localState = new osg::StateSet;
    osg::ref_ptr<osg::Viewport> viewport = new osg::Viewport(0, 0, kCullWidth, kCullHeight);
    osg::ref_ptr<osg::FrameStamp> frameStamp = new osg::FrameStamp;
    // All six planes and no small-feature culling, as our select pass; near
    // and far are fixed, not computed from the scene.
    cull->setCullingMode(osg::CullSettings::VIEW_FRUSTUM_CULLING);
    cull->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    const osg::Matrixd projection =
        osg::Matrixd::perspective(kCullFovyDegrees, double(kCullWidth) / kCullHeight, kCullNear, kCullFar);

    CullRun run;
    for (int f = -warmup; f < frames; ++f) {
        const int frame = std::max(f, 0);
        const CullCamera c = cullCamera(s, frame, frames);
        const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(c.eye.x, c.eye.y, c.eye.z),
                                                       osg::Vec3d(c.target.x, c.target.y, c.target.z),
                                                       osg::Vec3d(0, 1, 0));
        const auto start = std::chrono::steady_clock::now();
        // As SceneView::cullStage: reset, hand over the render graph, push
        // viewport and matrices, traverse, pop, sort and prune.
        frameStamp->setFrameNumber(static_cast<unsigned>(f + warmup));
        cull->reset();
        cull->setFrameStamp(frameStamp.get());
        cull->setTraversalNumber(frameStamp->getFrameNumber());
        stateGraph->clean();
        stage->reset();
        cull->setStateGraph(stateGraph.get());
        cull->setRenderStage(stage.get());
        stage->setViewport(viewport.get());
        stage->setInitialViewMatrix(new osg::RefMatrix(view));
        cull->pushStateSet(localState.get());
        cull->pushViewport(viewport.get());
        cull->pushProjectionMatrix(new osg::RefMatrix(projection));
        cull->pushModelViewMatrix(new osg::RefMatrix(view), osg::Transform::ABSOLUTE_RF);
        scene.root->accept(*cull);
        cull->popModelViewMatrix();
        cull->popProjectionMatrix();
        cull->popViewport();
        cull->popStateSet();
        stage->sort();
        stateGraph->prune();
        const auto stop = std::chrono::steady_clock::now();
        if (f < 0) continue;
        run.msPerFrame.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
        run.counts.push_back(countLeaves(*stage, scene));
    }
    // Tearing the scene down would take longer than the benchmark: every
    // LOD leaves the parent list of the shared Geodes, one erase at a time,
    // which is quadratic in the object count. The process ends right after.
    stage->reset();
    stateGraph->clean();
    static_cast<void>(scene.root.release());
    for (auto& level : scene.levels) static_cast<void>(level.release());
    return run;
}

} // namespace arcomp

#endif
