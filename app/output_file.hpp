#pragma once
// The file a command writes (`derive --out FILE`, `import --out SCENE.json`,
// `export-urdf --out ROBOT.urdf`): its folder checked before the work starts, so a path
// that cannot be written is a usage error now (exit 2), not a failure after the work.
#include <string>

namespace ll::cli {

// Throws UsageError(OutFolderMissing | OutFolderNotWritable) naming `out`.
void requireWritableOutputFile(const std::string& out);

}  // namespace ll::cli
