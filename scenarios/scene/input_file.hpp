#pragma once
/// Reading the files a scene names (the scene itself, STL meshes, initial.from_file, sweep
/// files) safely: only regular files are opened (a directory, a device such as /dev/zero, a FIFO
/// that would block the open, a socket are refused before anything reads them), their size is
/// taken from the file system and checked against a bound before any memory is allocated, and
/// a UTF-8 byte-order mark is dropped from text.
#include <cstddef>
#include <string>

namespace carom {

/// Throws SceneError "`context`: `path` is a directory / a character device / a FIFO ..., not
/// a regular file" when `path` is not a regular file, or "no such file" when it is missing.
/// `context` says where the path was given (e.g. "scene.toml:12: walls[0].file").
void require_regular_file(const std::string& path, const std::string& context);

/// The whole of the regular file `path` (require_regular_file), refused with SceneError when
/// it is larger than `max_bytes`, read in one allocation of its real length.
std::string read_regular_file(const std::string& path, const std::string& context, std::size_t max_bytes);

/// `text` without a leading UTF-8 byte-order mark (EF BB BF).
std::string without_bom(std::string text);

/// `message` with every run of more than `longest` characters without a space cut to its first
/// 40 characters and "...(N characters)": an error never echoes a huge token whole.
std::string shorten_long_tokens(const std::string& message, std::size_t longest = 200);

}  // namespace carom
