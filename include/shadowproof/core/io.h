#pragma once
/// File input and output with the guarantees a verification tool needs: reads are size-capped
/// with clear errors, and writes are atomic (a temporary file renamed into place), so an
/// interrupted run never leaves a half-written report or picture behind.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace shadowproof {

/// Default cap on the size of any input file (scenes, meshes, case files): 256 MiB.
inline constexpr std::size_t default_max_file_bytes = std::size_t(256) << 20;

/// Reads the whole file. Throws error "io.cannot_read" (missing, unreadable, a directory) or
/// "io.too_large" (over `max_bytes`; the message names the limit).
std::string read_file(const std::filesystem::path& path, std::size_t max_bytes = default_max_file_bytes);

/// Writes `content` to `path` atomically: to a temporary file in the same directory, flushed
/// and synced, then renamed over `path`. On any failure the temporary file is removed, `path`
/// keeps its previous content, and error "io.cannot_write" names the path and the reason.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace shadowproof
