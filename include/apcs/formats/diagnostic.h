#pragma once

// Diagnostic and Expected moved to the base layer, so that every layer (the animation layer's memory
// budget too) reports errors the same way. This header stays only until the files of the session
// and terminal layers that include it name apcs/base/diagnostic.h themselves (issue 27).
#include "apcs/base/diagnostic.h"
