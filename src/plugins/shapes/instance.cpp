// instance: places a `shapegroup` with its own transform (an Embree instance
// in the core: the group's geometry is shared, not copied). Hits report the
// group's shape (its BSDF) with the interaction mapped to world space.
// Instances cannot carry area emitters.
//
// | name     | type      | default  | meaning                                  | unit |
// |----------|-----------|----------|------------------------------------------|------|
// | (ref)    | shape     | required | <ref id="..."/> to a shapegroup          | -    |
// | to_world | transform | identity | group-to-world placement (any affine)    | -    |
//
//   <shape type="instance"> <ref id="tree"/> <transform name="to_world"> ... </transform> </shape>
#include <femto/core/plugin.h>
#include <femto/render/shape_group.h>

FEMTO_EXPORT_PLUGIN(femto::ShapeInstance, Shape, "instance", "Placed copy of a shapegroup")
