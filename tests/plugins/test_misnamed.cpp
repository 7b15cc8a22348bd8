// A plugin whose descriptor name differs from its file name (test_misnamed.so).
#include <femto/core/plugin.h>

#include "test_object.h"

FEMTO_EXPORT_PLUGIN(femto::test::TestTexture, Texture, "something_else", "descriptor name differs from file name")
