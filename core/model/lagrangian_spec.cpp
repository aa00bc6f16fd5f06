#include "core/model/lagrangian_spec.hpp"

namespace ll {

const char* toString(BodyShape shape) {
    switch (shape) {
        case BodyShape::Box: return "box";
        case BodyShape::Sphere: return "sphere";
        case BodyShape::Cylinder: return "cylinder";
        case BodyShape::Rod: return "rod";
    }
    return "?";
}

int sizeCount(BodyShape shape) {
    switch (shape) {
        case BodyShape::Box: return 3;
        case BodyShape::Cylinder: return 2;
        case BodyShape::Sphere:
        case BodyShape::Rod: return 1;
    }
    return 0;
}

}  // namespace ll
