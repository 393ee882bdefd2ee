// The colour type of the "h:color" and "v:color" properties. RenderSync reads those properties and
// from_engine_mesh() writes them, so both include this small header rather than each other. The
// type itself lives in core, since IndexedMesh carries colours too.
#pragma once

#include "hedge/core/color.h"
