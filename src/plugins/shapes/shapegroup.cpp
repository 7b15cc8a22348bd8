// shapegroup: a set of shapes that is not rendered itself but placed any
// number of times by `instance` shapes referring to it by id. The core builds
// the group once (its own Embree scene) however many instances use it.
// Groups cannot nest and cannot contain area emitters.
//
// | name     | type    | default  | meaning                                   | unit |
// |----------|---------|----------|-------------------------------------------|------|
// | (nested) | shape   | required | the shapes of the group, in group space   | -    |
//
//   <shape type="shapegroup" id="tree"> <shape type="ply"> ... </shape> </shape>
#include <femto/core/plugin.h>
#include <femto/render/shape_group.h>

FEMTO_EXPORT_PLUGIN(femto::ShapeGroup, Shape, "shapegroup", "Group of shapes placed by instances")
