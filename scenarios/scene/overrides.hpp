#pragma once
/// `--set key=value`: changes to a scene's TOML table made before it is validated.
///
/// The key is a dotted path ("collisions.default.e", "time.end"). A path component that meets
/// an array of tables is either an index ("species.1.diameter") or the `name` of one of its
/// tables ("species.fines.diameter"). Missing tables on the way are created; a key that the
/// scene does not know is then reported by the validation like any other unknown key. The
/// value is parsed as TOML ("0.9", "[0, 0, -9.81]", "\"tc\"", "true"); a value that is not valid
/// TOML is taken as a string, so `--set meta.name=my_run` works without quotes.
#include <cstdint>
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace carom {

/// Applies one "key=value" assignment. Throws SceneError for a malformed assignment or a path
/// that runs into a value that is not a table. `origin`: where the assignment was written
/// ("sweep.toml:12"); empty for the command line. The value's nodes then carry it as their
/// source, so that the scene's messages name it (TableReader::where) instead of saying
/// "(set on the command line)".
void apply_override(toml::table& scene, std::string_view assignment, const std::string& origin = "");

/// The value of `--seed N` (which is `--set initial.seed=N`): a whole number in
/// [0, 9223372036854775807], the range of initial.seed. Throws SceneError naming the text and
/// that range for anything else ("-1", "1.5", "abc", a number too large).
std::uint64_t parse_seed(std::string_view text);

}  // namespace carom
