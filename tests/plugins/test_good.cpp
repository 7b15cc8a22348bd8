// A well-formed plugin: loads and creates a TestTexture.
#include <femto/core/plugin.h>

#include "test_object.h"

FEMTO_EXPORT_PLUGIN(femto::test::TestTexture, Texture, "test_good", "test-only texture that loads")
