#pragma once
/// SHA-256 (FIPS 180-4) of a byte string, as 64 lowercase hex digits. Used
/// to tie a certificate to the exact bytes of its data file.

#include <string>
#include <string_view>

namespace lpvid {

std::string sha256_hex(std::string_view bytes);

}  // namespace lpvid
