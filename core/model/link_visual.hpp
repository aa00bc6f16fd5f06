#pragma once
// A robot's links as its own description draws them (a URDF's <visual> elements), beside
// the DH stick figure the window draws by default: each link's frame as its description
// places it, and the shapes fixed to it (a mesh file, or a box, cylinder or sphere).
// A link rides on a DH frame: body 0 is the base (fixed in the world), body i moves with
// frame i (link i). The file keeps them under "robot" → "links" (docs/user/scene-format.md);
// a mesh path is absolute or relative to the scene file.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace ll {

struct LinkShape {
    enum class Kind { Mesh, Box, Cylinder, Sphere };
    Kind kind = Kind::Mesh;
    std::string mesh;  // Mesh: the file (STL; DAE, OBJ where OpenSceneGraph reads them)
    Eigen::Vector3d size =
        Eigen::Vector3d::Ones();  // Mesh: scale; Box: edges [m]; Cylinder: (radius, radius, length) [m]; Sphere: radius ×3 [m]
    Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // in the link's frame
    std::array<double, 4> rgba{-1, -1, -1, -1};                // a colour (0..1); r < 0: the link's colour
    bool coloured() const { return rgba[0] >= 0; }
};

struct LinkVisual {
    std::string name;                                         // the description's name for the link
    int body = 0;                                             // 0: the base; i: moves with DH frame i
    Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();  // the link's frame in frame `body` (body 0: in the world)
    std::vector<LinkShape> shapes;
};

}  // namespace ll
