#include "ui/paint/osg_scene.hpp"

#include "core/visual/frame_labels.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <osg/BlendFunc>
#include <osg/Depth>
#include <osg/Geode>
#include <osg/Light>
#include <osg/LightSource>
#include <osg/LineWidth>
#include <osg/Material>
#include <osg/Point>
#include <osg/ShapeDrawable>
#include <osgDB/ReadFile>
#include <osgDB/Options>
#include <osgText/Text>

namespace ll::ui {
namespace {

osg::Matrixd toOsgMatrix(const Eigen::Matrix4d& m) {
    // Eigen stores M column by column; OSG multiplies row vectors, v' = v M_osg with
    // M_osg = Mᵀ stored row by row: the same 16 numbers in the same order.
    return osg::Matrixd(m.data());
}

osg::Vec3 toOsg(const Eigen::Vector3d& v) { return osg::Vec3(float(v.x()), float(v.y()), float(v.z())); }

void setMaterial(osg::Node& node, const Rgba& c) {
    auto* material = new osg::Material;
    const osg::Vec4 colour(c.r, c.g, c.b, c.a);
    material->setDiffuse(osg::Material::FRONT_AND_BACK, colour);
    material->setAmbient(osg::Material::FRONT_AND_BACK, osg::Vec4(colour.r() * 0.45f, colour.g() * 0.45f, colour.b() * 0.45f, 1));
    material->setSpecular(osg::Material::FRONT_AND_BACK, osg::Vec4(0.3f, 0.3f, 0.3f, 1));
    material->setShininess(osg::Material::FRONT_AND_BACK, 40);
    node.getOrCreateStateSet()->setAttributeAndModes(material, osg::StateAttribute::ON);
}

osg::ref_ptr<osg::TessellationHints> hints() {
    osg::ref_ptr<osg::TessellationHints> h = new osg::TessellationHints;
    h->setDetailRatio(1.6f);
    return h;
}

void addShape(osg::Geode& geode, osg::Shape* shape) { geode.addDrawable(new osg::ShapeDrawable(shape, hints().get())); }

// A mesh file read by OpenSceneGraph's plugins (STL; DAE, OBJ where Debian's build reads
// them), kept in its registry's cache so a rebuild after an edit reads no file again;
// null with `failure` set when there is none or it cannot be read.
osg::ref_ptr<osg::Node> meshNode(const std::string& file, const std::string& directory, std::string& failure) {
    std::string path = file;
    if (path.rfind("file://", 0) == 0) path = path.substr(7);
    if (path.rfind("package://", 0) == 0) {
        failure = file + ": package:// not resolved";
        return nullptr;
    }
    std::filesystem::path resolved(path);
    if (resolved.is_relative() && !directory.empty()) resolved = std::filesystem::path(directory) / resolved;
    std::error_code error;
    if (!std::filesystem::is_regular_file(resolved, error)) {
        failure = resolved.string() + ": no such file";
        return nullptr;
    }
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options;
    options->setObjectCacheHint(osgDB::Options::CACHE_NODES);
    osg::ref_ptr<osg::Node> node = osgDB::readRefNodeFile(resolved.string(), options.get());
    if (!node) failure = resolved.string() + ": OpenSceneGraph cannot read it";
    return node;
}

// The solid of a part in its own frame; stretching parts at unit length. A mesh that
// cannot be read is an empty node, and why is appended to `failures`.
osg::ref_ptr<osg::Node> solid(const VisualPart& part, const std::string& meshDirectory, std::vector<std::string>& failures) {
    if (part.shape == PartShape::Mesh) {
        osg::ref_ptr<osg::MatrixTransform> scaled = new osg::MatrixTransform(osg::Matrixd::scale(part.box.x(), part.box.y(), part.box.z()));
        std::string failure;
        if (osg::ref_ptr<osg::Node> mesh = meshNode(part.mesh, meshDirectory, failure)) scaled->addChild(mesh);
        else failures.push_back(failure);
        setMaterial(*scaled, part.color);
        return scaled;
    }
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    const float r = float(part.radius), length = float(part.length);
    switch (part.shape) {
        case PartShape::Box:
            addShape(*geode, new osg::Box(osg::Vec3(), float(part.box.x()), float(part.box.y()), float(part.box.z())));
            break;
        case PartShape::Sphere: addShape(*geode, new osg::Sphere(osg::Vec3(), r)); break;
        case PartShape::Cylinder: addShape(*geode, new osg::Cylinder(osg::Vec3(), r, length)); break;
        case PartShape::Rod: addShape(*geode, new osg::Cylinder(osg::Vec3(), r, 1.0f)); break;
        case PartShape::Bar: addShape(*geode, new osg::Box(osg::Vec3(), 2 * r, 2 * r, 1.0f)); break;
        case PartShape::Sleeve: {
            const float wall = r / 4, mid = r - wall / 2;
            addShape(*geode, new osg::Box(osg::Vec3(mid, 0, 0), wall, 2 * r, length));
            addShape(*geode, new osg::Box(osg::Vec3(-mid, 0, 0), wall, 2 * r, length));
            addShape(*geode, new osg::Box(osg::Vec3(0, mid, 0), 2 * r - 2 * wall, wall, length));
            addShape(*geode, new osg::Box(osg::Vec3(0, -mid, 0), 2 * r - 2 * wall, wall, length));
            break;
        }
        case PartShape::Mesh: break;
    }
    setMaterial(*geode, part.color);
    return geode;
}

// x, y, z arrows of length L (red, green, blue), each a shaft and a cone.
osg::ref_ptr<osg::Group> triad(double L) {
    osg::ref_ptr<osg::Group> group = new osg::Group;
    const float l = float(L);
    const struct {
        osg::Quat turn;  // takes z to the axis
        Rgba color;
    } axes[] = {{osg::Quat(osg::PI_2, osg::Y_AXIS), {0.85f, 0.12f, 0.12f, 1}},
                {osg::Quat(-osg::PI_2, osg::X_AXIS), {0.1f, 0.62f, 0.1f, 1}},
                {osg::Quat(), {0.12f, 0.3f, 0.9f, 1}}};
    for (const auto& axis : axes) {
        osg::ref_ptr<osg::MatrixTransform> turn = new osg::MatrixTransform(osg::Matrixd::rotate(axis.turn));
        osg::ref_ptr<osg::Geode> arrow = new osg::Geode;
        addShape(*arrow, new osg::Cylinder(osg::Vec3(0, 0, 0.39f * l), 0.03f * l, 0.78f * l));
        // osg::Cone's centre sits a quarter of its height above its base.
        addShape(*arrow, new osg::Cone(osg::Vec3(0, 0, (0.78f + 0.25f * 0.22f) * l), 0.075f * l, 0.22f * l));
        setMaterial(*arrow, axis.color);
        turn->addChild(arrow);
        group->addChild(turn);
    }
    return group;
}

// A font of the scene's own, not the one osgDB caches for the process: its glyph texture
// then holds only this scene's labels, so a label's pixels do not depend on the text drawn
// before (a lesson's view looked 6 pixels different after other scenes' labels).
osg::ref_ptr<osgText::Font> labelFont() {
    static const char* const candidates[] = {"/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf",
                                             "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"};
    osg::ref_ptr<osgDB::Options> own = new osgDB::Options;
    own->setObjectCacheHint(osgDB::Options::CACHE_NONE);
    for (const char* path : candidates)
        if (std::filesystem::exists(path))
            if (osg::ref_ptr<osgText::Font> font = osgText::readRefFontFile(path, own.get())) return font;
    return osgText::Font::getDefaultFont();
}

osg::ref_ptr<osgText::Text> label(const std::string& text, double axisLength, double pixels, osgText::Font* font) {
    osg::ref_ptr<osgText::Text> t = new osgText::Text;
    t->setFont(font);
    t->setText(text);
    t->setCharacterSizeMode(osgText::Text::SCREEN_COORDS);
    t->setCharacterSize(float(pixels));
    t->setAxisAlignment(osgText::Text::SCREEN);
    t->setAlignment(osgText::Text::RIGHT_TOP);
    const float back = -float(kLabelBack * axisLength);  // core/visual/frame_labels places it the same
    t->setPosition(osg::Vec3(back, back, back));
    t->setColor(osg::Vec4(0.1f, 0.1f, 0.12f, 1));
    t->setBackdropType(osgText::Text::OUTLINE);
    t->setBackdropColor(osg::Vec4(1, 1, 1, 0.9f));
    return t;
}

// Geometry whose `count` vertices change every frame (the trail, the drop lines, the
// leader lines): no display list, vertex buffers, the vertices allocated once.
osg::ref_ptr<osg::Geometry> dynamicGeometry(unsigned count) {
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setDataVariance(osg::Object::DYNAMIC);
    g->setUseDisplayList(false);
    g->setUseVertexBufferObjects(true);
    g->setVertexArray(new osg::Vec3Array(count));
    return g;
}

// Lines on the ground plane every `spacing`, every fifth darker.
osg::ref_ptr<osg::Geode> grid(const VisualScene& scene) {
    const VisualGround& g = scene.ground;
    const Eigen::Vector3d up = scene.up.normalized();
    Eigen::Vector3d e1 = std::abs(up.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    e1 = (e1 - e1.dot(up) * up).normalized();
    const Eigen::Vector3d e2 = up.cross(e1);
    // Lines on multiples of the spacing, so the grid does not shift with the bounds.
    const Eigen::Vector3d c = g.centre;
    const double c1 = std::round(c.dot(e1) / g.spacing) * g.spacing, c2 = std::round(c.dot(e2) / g.spacing) * g.spacing;
    const Eigen::Vector3d origin = c + (c1 - c.dot(e1)) * e1 + (c2 - c.dot(e2)) * e2;
    const int half = static_cast<int>(std::lround(g.halfSize / g.spacing));

    osg::ref_ptr<osg::Vec3Array> vertices = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec4Array> colours = new osg::Vec4Array;
    const double H = half * g.spacing;
    for (int k = -half; k <= half; ++k) {
        for (int direction = 0; direction < 2; ++direction) {
            const Eigen::Vector3d along = direction == 0 ? e1 : e2, across = direction == 0 ? e2 : e1;
            const double offset = k * g.spacing;
            const double position = (direction == 0 ? c2 : c1) + offset;
            const bool heavy = static_cast<long>(std::lround(position / g.spacing)) % 5 == 0;
            vertices->push_back(toOsg(Eigen::Vector3d(origin + offset * across - H * along)));
            vertices->push_back(toOsg(Eigen::Vector3d(origin + offset * across + H * along)));
            const osg::Vec4 colour = heavy ? osg::Vec4(0.45f, 0.48f, 0.52f, 1) : osg::Vec4(0.68f, 0.7f, 0.73f, 1);
            colours->push_back(colour);
            colours->push_back(colour);
        }
    }
    osg::ref_ptr<osg::Geometry> lines = new osg::Geometry;
    lines->setVertexArray(vertices);
    lines->setColorArray(colours, osg::Array::BIND_PER_VERTEX);
    lines->addPrimitiveSet(new osg::DrawArrays(GL_LINES, 0, static_cast<int>(vertices->size())));
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(lines);
    osg::StateSet* state = geode->getOrCreateStateSet();
    state->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
    state->setAttributeAndModes(new osg::LineWidth(1.5f));
    // Drawn first and writing no depth: where two of its lines cross, the later one is on
    // top, always. With depth written the crossing pixels went to whichever line's depth
    // rounded nearer, and the same view of a lesson differed in 2 pixels between two runs.
    state->setRenderBinDetails(-1, "RenderBin");
    state->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0, 1, false));
    return geode;
}

osg::Matrixd partMatrix(const VisualPart& part, bool stretch) {
    if (!stretch) return toOsgMatrix(part.pose.matrix());
    const Eigen::Affine3d scaled = part.pose * Eigen::Scaling(1.0, 1.0, std::max(part.length, 1e-9));
    return toOsgMatrix(scaled.matrix());
}

}  // namespace

OsgScene::OsgScene(const VisualScene& scene, const OsgSceneOptions& options) : options_(options), root_(new osg::Group) {
    // Stretched parts scale their normals: renormalize.
    root_->getOrCreateStateSet()->setMode(GL_NORMALIZE, osg::StateAttribute::ON);
    // A sky light beside the viewer's headlight: from straight above (the scene's up), so
    // faces turned up stay lit from any camera and the tops of links read as tops.
    {
        osg::ref_ptr<osg::Light> sky = new osg::Light(1);
        const Eigen::Vector3d up = scene.up.normalized();
        sky->setPosition(osg::Vec4(float(up.x()), float(up.y()), float(up.z()), 0.0f));  // directional
        sky->setAmbient(osg::Vec4(0, 0, 0, 1));
        sky->setDiffuse(osg::Vec4(0.45f, 0.45f, 0.45f, 1));
        sky->setSpecular(osg::Vec4(0, 0, 0, 1));
        osg::ref_ptr<osg::LightSource> source = new osg::LightSource;
        source->setLight(sky);
        source->setReferenceFrame(osg::LightSource::ABSOLUTE_RF);
        source->setLocalStateSetModes(osg::StateAttribute::ON);
        source->setStateSetModes(*root_->getOrCreateStateSet(), osg::StateAttribute::ON);
        root_->addChild(source);
    }
    if (!scene.frames.empty() && scene.frames.back().axisLength > 0) frameLength_ = scene.frames.back().axisLength;
    for (const VisualPart& part : scene.parts) {
        osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform;
        transform->setDataVariance(osg::Object::DYNAMIC);
        transform->setName(part.name);
        transform->addChild(solid(part, options_.meshDirectory, meshFailures_));
        parts_.push_back(transform);
        roles_.push_back(part.role);
        stretch_.push_back(stretches(part.shape));
        // a link's parts in its colour when emphasised (its COM marker too)
        colours_.push_back(part.role == PartRole::CentreOfMass && part.coordinate >= 0 ? linkColor(part.coordinate) : part.color);
        built_.push_back(part.color);
        root_->addChild(transform);
        // A joint's axis, shown when a picked entry depends on its coordinate: a thin rod
        // along the joint's z through the marker, well past it on both sides.
        osg::ref_ptr<osg::MatrixTransform> axis;
        osg::ref_ptr<osg::Geode> line;
        if (part.role == PartRole::Joint) {
            axis = new osg::MatrixTransform;
            axis->setDataVariance(osg::Object::DYNAMIC);
            line = new osg::Geode;
            addShape(*line, new osg::Cylinder(osg::Vec3(), float(0.004 * scene.scale), float(0.45 * scene.scale)));
            axis->addChild(line);
            axis->setNodeMask(0u);
            root_->addChild(axis);
        }
        axes_.push_back(axis);
        axisGeodes_.push_back(line);
    }
    if (options_.frames) {
        osg::ref_ptr<osgText::Font> font = options_.frameLabels ? labelFont() : nullptr;
        for (const VisualFrame& frame : scene.frames) {
            osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform;
            transform->setDataVariance(osg::Object::DYNAMIC);
            transform->addChild(triad(frame.axisLength));
            osg::ref_ptr<osgText::Text> drawn;
            osg::ref_ptr<osg::Geode> leaderGeode;
            if (font && !frame.label.empty()) {  // frames sharing an origin share one label
                osg::ref_ptr<osg::Geode> text = new osg::Geode;
                drawn = label(frame.label, frame.axisLength, options_.labelPixels, font.get());
                drawn->setDataVariance(osg::Object::DYNAMIC);
                text->addDrawable(drawn);
                // Labels stay readable in front of the solids.
                text->getOrCreateStateSet()->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
                text->getOrCreateStateSet()->setRenderBinDetails(20, "RenderBin");
                transform->addChild(text);
                // The leader line of a label moved off its frame (hidden until then).
                osg::ref_ptr<osg::Geometry> leader = dynamicGeometry(2);
                osg::ref_ptr<osg::Vec4Array> colour = new osg::Vec4Array(1);
                (*colour)[0] = osg::Vec4(0.15f, 0.15f, 0.2f, 0.8f);
                leader->setColorArray(colour, osg::Array::BIND_OVERALL);
                leader->addPrimitiveSet(new osg::DrawArrays(GL_LINES, 0, 2));
                leaderGeode = new osg::Geode;
                leaderGeode->addDrawable(leader);
                osg::StateSet* state = leaderGeode->getOrCreateStateSet();
                state->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
                state->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
                state->setRenderBinDetails(19, "RenderBin");
                state->setAttributeAndModes(new osg::LineWidth(1.2f));
                leaderGeode->setNodeMask(0u);
                transform->addChild(leaderGeode);
            }
            labels_.push_back(drawn);
            leaderGeodes_.push_back(leaderGeode);
            frames_.push_back(transform);
            root_->addChild(transform);
        }
    }
    groundGroup_ = new osg::Group;
    root_->addChild(groundGroup_);
    updateGround(scene);

    if (options_.trail && scene.endEffector >= 0) {
        trail_ = dynamicGeometry(maxTrailPoints);
        osg::ref_ptr<osg::Vec4Array> colours = new osg::Vec4Array(maxTrailPoints);
        trail_->setColorArray(colours, osg::Array::BIND_PER_VERTEX);
        trail_->addPrimitiveSet(new osg::DrawArrays(GL_LINE_STRIP, 0, 0));
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(trail_);
        osg::StateSet* state = geode->getOrCreateStateSet();
        state->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
        state->setMode(GL_BLEND, osg::StateAttribute::ON);
        state->setAttributeAndModes(new osg::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA));
        state->setAttributeAndModes(new osg::LineWidth(3.0f));
        state->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0, 1, false));
        state->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
        root_->addChild(geode);
    }
    if (options_.dropLines && !scene.dropLines.empty()) {
        // Where each mass stands over the ground: a thin grey line down and a dot at its
        // foot, which read as height on a projector and on software GL alike.
        const unsigned count = static_cast<unsigned>(2 * scene.dropLines.size());
        drops_ = dynamicGeometry(count);
        osg::ref_ptr<osg::Vec4Array> colour = new osg::Vec4Array(1);
        (*colour)[0] = osg::Vec4(0.25f, 0.27f, 0.32f, 0.75f);
        drops_->setColorArray(colour, osg::Array::BIND_OVERALL);
        drops_->addPrimitiveSet(new osg::DrawArrays(GL_LINES, 0, static_cast<GLsizei>(count)));
        osg::ref_ptr<osg::DrawElementsUShort> feet = new osg::DrawElementsUShort(GL_POINTS);
        for (unsigned k = 1; k < count; k += 2) feet->push_back(static_cast<unsigned short>(k));
        drops_->addPrimitiveSet(feet);
        dropGeode_ = new osg::Geode;
        dropGeode_->addDrawable(drops_);
        osg::StateSet* state = dropGeode_->getOrCreateStateSet();
        state->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
        state->setMode(GL_BLEND, osg::StateAttribute::ON);
        state->setAttributeAndModes(new osg::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA));
        state->setAttributeAndModes(new osg::LineWidth(1.5f));
        state->setAttributeAndModes(new osg::Point(7.0f));
        state->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
        root_->addChild(dropGeode_);
    }
    setShowLook(options_.look);
    update(scene);
}

void OsgScene::setDropLinesVisible(bool on) {
    if (dropGeode_) dropGeode_->setNodeMask(on ? ~0u : 0u);
}

void OsgScene::update(const VisualScene& scene) {
    for (std::size_t i = 0; i < parts_.size(); ++i) {
        parts_[i]->setMatrix(partMatrix(scene.parts[i], stretch_[i]));
        if (axes_[i]) axes_[i]->setMatrix(toOsgMatrix(scene.parts[i].pose.matrix()));
    }
    for (std::size_t k = 0; k < frames_.size(); ++k) frames_[k]->setMatrix(toOsgMatrix(scene.frames[k].pose.matrix()));
    if (drops_) {
        auto& vertices = static_cast<osg::Vec3Array&>(*drops_->getVertexArray());
        for (std::size_t k = 0; k < scene.dropLines.size() && 2 * k + 1 < vertices.size(); ++k) {
            vertices[2 * k] = toOsg(scene.dropLines[k].first);
            vertices[2 * k + 1] = toOsg(scene.dropLines[k].second);
        }
        vertices.dirty();
        drops_->dirtyBound();
    }
}

void OsgScene::updateGround(const VisualScene& scene) {
    groundGroup_->removeChildren(0, groundGroup_->getNumChildren());
    if (options_.grid) groundGroup_->addChild(grid(scene));
}

void OsgScene::setMovingFrame(const Eigen::Isometry3d* pose) {
    if (!pose) {
        if (moving_) moving_->setNodeMask(0);
        return;
    }
    if (!moving_) {
        moving_ = new osg::MatrixTransform;
        moving_->setDataVariance(osg::Object::DYNAMIC);
        moving_->addChild(triad(1.8 * frameLength_));
        // Over the solids: the frame is what the student follows, even inside a link.
        moving_->getOrCreateStateSet()->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
        moving_->getOrCreateStateSet()->setRenderBinDetails(15, "RenderBin");
        root_->addChild(moving_);
    }
    moving_->setNodeMask(~0u);
    moving_->setMatrix(toOsgMatrix(pose->matrix()));
}

namespace {

// A polyline over the solids (the group's state: no lighting, no depth test) with its
// end points as dots and an outlined label; `width` [px] when it differs from the group's.
osg::ref_ptr<osg::Geode> overlayLine(const std::vector<Eigen::Vector3d>& points, const osg::Vec4& colour, const std::string& label,
                                     const Eigen::Vector3d& labelAt, double labelPixels, float width = 0) {
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    if (width > 0) geode->getOrCreateStateSet()->setAttributeAndModes(new osg::LineWidth(width));
    if (!points.empty()) {
        osg::ref_ptr<osg::Geometry> line = new osg::Geometry;
        osg::ref_ptr<osg::Vec3Array> vertices = new osg::Vec3Array;
        for (const Eigen::Vector3d& p : points) vertices->push_back(toOsg(p));
        line->setVertexArray(vertices);
        osg::ref_ptr<osg::Vec4Array> colours = new osg::Vec4Array(1);
        (*colours)[0] = colour;
        line->setColorArray(colours, osg::Array::BIND_OVERALL);
        line->addPrimitiveSet(new osg::DrawArrays(GL_LINE_STRIP, 0, static_cast<GLsizei>(vertices->size())));
        osg::ref_ptr<osg::DrawElementsUShort> ends = new osg::DrawElementsUShort(GL_POINTS);
        ends->push_back(0);
        if (vertices->size() > 1) ends->push_back(static_cast<unsigned short>(vertices->size() - 1));
        line->addPrimitiveSet(ends);
        geode->addDrawable(line);
    }
    if (!label.empty()) {
        osg::ref_ptr<osgText::Text> text = new osgText::Text;
        text->setFont(labelFont().get());
        text->setText(label, osgText::String::ENCODING_UTF8);
        text->setCharacterSizeMode(osgText::Text::SCREEN_COORDS);
        text->setCharacterSize(float(labelPixels));
        text->setAxisAlignment(osgText::Text::SCREEN);
        text->setAlignment(osgText::Text::LEFT_CENTER);
        text->setPosition(toOsg(labelAt));
        text->setColor(colour);
        text->setBackdropType(osgText::Text::OUTLINE);
        text->setBackdropColor(osg::Vec4(1, 1, 1, 0.9f));
        geode->addDrawable(text);
    }
    return geode;
}

// A group drawn over the solids, lines `width` wide.
osg::ref_ptr<osg::Group> overlayGroup(float width) {
    osg::ref_ptr<osg::Group> group = new osg::Group;
    osg::StateSet* state = group->getOrCreateStateSet();
    state->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
    state->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
    state->setRenderBinDetails(16, "RenderBin");
    state->setAttributeAndModes(new osg::LineWidth(width));
    state->setAttributeAndModes(new osg::Point(6.0f));
    return group;
}

}  // namespace

void OsgScene::setDimensions(const std::vector<DhDimension>* dimensions) {
    if (dimensions_) root_->removeChild(dimensions_);
    dimensions_ = nullptr;
    if (!dimensions || dimensions->empty()) return;
    dimensions_ = overlayGroup(2.5f);
    for (const DhDimension& d : *dimensions) {
        // θ orange, d blue, a green, α purple: the same in every row.
        const osg::Vec4 colour = d.parameter == DhParameter::Theta ? osg::Vec4(0.85f, 0.45f, 0.0f, 1)
                                 : d.parameter == DhParameter::D   ? osg::Vec4(0.0f, 0.45f, 0.75f, 1)
                                 : d.parameter == DhParameter::A   ? osg::Vec4(0.0f, 0.55f, 0.3f, 1)
                                                                   : osg::Vec4(0.6f, 0.2f, 0.65f, 1);
        dimensions_->addChild(overlayLine(d.points, colour, d.label, d.labelAt, 0.8 * options_.labelPixels));
    }
    root_->addChild(dimensions_);
}

void OsgScene::setConstruction(const std::vector<ConstructionMark>* marks) {
    if (construction_) root_->removeChild(construction_);
    construction_ = nullptr;
    if (!marks || marks->empty()) return;
    construction_ = overlayGroup(2.0f);
    construction_->getOrCreateStateSet()->setAttributeAndModes(new osg::Point(9.0f));
    using Kind = ConstructionMarkKind;
    for (const ConstructionMark& m : *marks) {
        // The axes grey, those in use orange, the normal magenta, frames red/green/blue as the triads.
        osg::Vec4 colour(0.45f, 0.45f, 0.45f, 1);
        float width = 0;
        switch (m.kind) {
            case Kind::Axis: width = 1.5f; break;
            case Kind::AxisInUse: colour = osg::Vec4(0.9f, 0.5f, 0.0f, 1), width = 3.5f; break;
            case Kind::Normal: colour = osg::Vec4(0.8f, 0.1f, 0.6f, 1), width = 3.0f; break;
            case Kind::Origin: colour = osg::Vec4(0.1f, 0.1f, 0.1f, 1); break;
            case Kind::FrameX: colour = osg::Vec4(0.85f, 0.1f, 0.1f, 1), width = 3.5f; break;
            case Kind::FrameY: colour = osg::Vec4(0.1f, 0.6f, 0.1f, 1), width = 3.5f; break;
            case Kind::FrameZ: colour = osg::Vec4(0.1f, 0.25f, 0.9f, 1), width = 3.5f; break;
            case Kind::OverlayFrame: colour = osg::Vec4(0.55f, 0.35f, 0.7f, 1), width = 1.5f; break;
        }
        construction_->addChild(overlayLine(m.points, colour, m.label, m.labelAt, 0.85 * options_.labelPixels, width));
    }
    root_->addChild(construction_);
}

void OsgScene::placeLabels(const VisualScene& scene, const CameraView& view, int width, int height) {
    if (labels_.empty() || width <= 0 || height <= 0) return;
    std::vector<LabelBox> boxes = frameLabelBoxes(scene, view, width, height, options_.labelPixels);
    separateLabels(boxes, width, height, bodyBoxes(scene, view, width, height));
    const PictureAxes axes = pictureAxes(view);
    for (const LabelBox& box : boxes) {
        const std::size_t k = static_cast<std::size_t>(box.frame);
        if (k >= labels_.size() || !labels_[k]) continue;
        const VisualFrame& frame = scene.frames[k];
        const Eigen::Vector3d local = Eigen::Vector3d::Constant(-kLabelBack * frame.axisLength);
        const Eigen::Vector3d anchor = frame.pose * local;
        // Pixels to metres at the anchor's depth.
        const double perPixel = 2 * std::max((anchor - view.eye).dot(axes.forward), 1e-9) * axes.tanHalfFovy / height;
        const Eigen::Vector3d moved = anchor + perPixel * ((box.right - box.anchorX) * axes.right - (box.top - box.anchorY) * axes.up);
        const Eigen::Vector3d at = frame.pose.inverse() * moved;
        labels_[k]->setPosition(toOsg(at));
        const bool shifted = box.moved();
        leaderGeodes_[k]->setNodeMask(shifted ? ~0u : 0u);
        if (shifted) {
            osg::Geometry& leader = *leaderGeodes_[k]->getDrawable(0)->asGeometry();
            auto& v = static_cast<osg::Vec3Array&>(*leader.getVertexArray());
            v[0] = toOsg(local);
            v[1] = toOsg(at);
            v.dirty();
            leader.dirtyBound();
        }
    }
}

void OsgScene::setFrameVisible(int k, bool on) {
    if (k >= 0 && k < static_cast<int>(frames_.size())) frames_[static_cast<std::size_t>(k)]->setNodeMask(on ? ~0u : 0u);
}

void OsgScene::setTrail(const std::vector<Eigen::Vector3d>& points) {
    if (!trail_) return;
    auto* vertices = static_cast<osg::Vec3Array*>(trail_->getVertexArray());
    auto* colours = static_cast<osg::Vec4Array*>(trail_->getColorArray());
    const int count = std::min(static_cast<int>(points.size()), maxTrailPoints);
    const int first = static_cast<int>(points.size()) - count;
    for (int k = 0; k < count; ++k) {
        (*vertices)[k] = toOsg(points[first + k]);
        const float age = count > 1 ? float(k) / float(count - 1) : 1.0f;  // 0 oldest .. 1 newest
        (*colours)[k] = osg::Vec4(0.8f, 0.1f, 0.15f, age * age);
    }
    static_cast<osg::DrawArrays*>(trail_->getPrimitiveSet(0))->setCount(count);
    vertices->dirty();
    colours->dirty();
    trail_->dirtyBound();
}

bool OsgScene::hasLook() const { return std::find(roles_.begin(), roles_.end(), PartRole::Look) != roles_.end(); }

void OsgScene::setShowLook(bool on) {
    showsLook_ = on && hasLook() && meshFailures_.empty();
    for (std::size_t i = 0; i < parts_.size(); ++i) {
        const PartRole role = roles_[i];
        if (role == PartRole::Look) parts_[i]->setNodeMask(showsLook_ ? ~0u : 0u);
        else if (role == PartRole::Link || role == PartRole::Joint || role == PartRole::Pedestal) parts_[i]->setNodeMask(showsLook_ ? 0u : ~0u);
    }
}

void OsgScene::setPartVisible(int i, bool on) { parts_[static_cast<std::size_t>(i)]->setNodeMask(on ? ~0u : 0u); }

void OsgScene::setPartHighlighted(int i, bool on) {
    osg::MatrixTransform& node = *parts_[static_cast<std::size_t>(i)];
    if (on) {
        auto* material = new osg::Material;
        material->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(1.0f, 0.75f, 0.1f, 1.0f));
        material->setEmission(osg::Material::FRONT_AND_BACK, osg::Vec4(0.45f, 0.3f, 0.0f, 1.0f));
        node.getOrCreateStateSet()->setAttributeAndModes(material, osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
    } else if (node.getStateSet()) {
        node.getStateSet()->removeAttribute(osg::StateAttribute::MATERIAL);
    }
}

void OsgScene::setEmphasis(const VisualEmphasis& emphasis) {
    static const Rgba faded{0.84f, 0.85f, 0.87f, 1.0f};
    for (std::size_t i = 0; i < parts_.size(); ++i) {
        osg::Node& solid = *parts_[i]->getChild(0);
        const float strength = emphasis.active() && i < emphasis.strength.size() ? emphasis.strength[i] : NAN;
        if (std::isnan(strength)) {
            setMaterial(solid, built_[i]);
        } else if (strength < 0) {
            setMaterial(solid, faded);
        } else {
            // The link's own colour, from pale (a small share) to full and glowing (all of it).
            const Rgba& c = colours_[i];
            const float w = 0.35f + 0.65f * strength;
            setMaterial(solid, {faded.r + w * (c.r - faded.r), faded.g + w * (c.g - faded.g), faded.b + w * (c.b - faded.b), 1});
            auto* material = static_cast<osg::Material*>(solid.getStateSet()->getAttribute(osg::StateAttribute::MATERIAL));
            material->setEmission(osg::Material::FRONT_AND_BACK,
                                  osg::Vec4(0.35f * strength * c.r, 0.35f * strength * c.g, 0.35f * strength * c.b, 1));
        }
        if (!axes_[i]) continue;
        const AxisMark mark = emphasis.active() && i < emphasis.axes.size() ? emphasis.axes[i] : AxisMark::None;
        axes_[i]->setNodeMask(mark == AxisMark::None ? 0u : ~0u);
        // a coordinate's axis dark, a velocity's red (the q̇_j that multiplies a c_ij)
        if (mark != AxisMark::None)
            setMaterial(*axisGeodes_[i], mark == AxisMark::Velocity ? Rgba{0.86f, 0.1f, 0.24f, 1} : Rgba{0.12f, 0.13f, 0.18f, 1});
    }
}

void applyCameraView(osg::Camera& camera, const CameraView& view, double aspect) {
    camera.setViewMatrixAsLookAt(toOsg(view.eye), toOsg(view.centre), toOsg(view.up));
    camera.setProjectionMatrixAsPerspective(view.fovy, aspect, view.zNear, view.zFar);
}

}  // namespace ll::ui
