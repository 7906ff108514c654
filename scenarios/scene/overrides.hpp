#pragma once
/// `--set key=value`: changes to a scene's TOML table made before it is validated.
///
/// The key is a dotted path ("collisions.default.e", "time.end"). A path component that meets
/// an array of tables is either an index ("species.1.diameter") or the `name` of one of its
/// tables ("species.fines.diameter"). Missing tables on the way are created; a key that the
/// scene does not know is then reported by the validation like any other unknown key. The
/// value is parsed as TOML ("0.9", "[0, 0, -9.81]", "\"tc\"", "true"); a value that is not valid
/// TOML is taken as a string, so `--set meta.name=my_run` works without quotes.
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace carom {

/// Applies one "key=value" assignment. Throws SceneError for a malformed assignment or a path
/// that runs into a value that is not a table.
void apply_override(toml::table& scene, std::string_view assignment);

}  // namespace carom
