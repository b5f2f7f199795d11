#pragma once

namespace apcs {

// Which surface gives the interior points' paths (SPEC §5.3, `--surface`): the transfinite blend
// that keeps the edge paths' whole shape (the default), or the thesis' own Ferguson surface of
// Ch. 3.2 (§5.3.1), which sees only the edges' end tangents.
enum class SurfaceConstruction { blend, ferguson };

} // namespace apcs
