#pragma once
/// The file edge of certification: certify.h computes and checks its
/// certificates in memory; a front end (the CLI, a test, a bench) places
/// them in files here. A certificate names its data file relative to its
/// own folder (verify/certificate/certificate_file.h placed_at).
///
/// The naming scheme: the consistency or invalidation certificate at the
/// given path, the lower end's dual certificate beside it as
/// "<stem>.lower.json" (a.cert.json → a.cert.lower.json), which
/// `lpvid jobs merge` looks for.

#include <map>
#include <string>

#include "certify/certify_types.h"

namespace lpvid {

/// Where the lower end's (dual) certificate of `certificate_path` goes.
std::string lower_certificate_path(const std::string& certificate_path);

/// The files written for one certification (empty: none).
struct CertificateFiles {
  std::string certificate;  ///< "consistent" or "invalidated"
  std::string lower;        ///< "lower_bound"
};

/// The bytes of written files, by path.
using WrittenFiles = std::map<std::string, std::string>;

/// Writes b.certificate at `certificate_path` and b.lower.certificate at
/// lower_certificate_path(certificate_path), those that exist. Throws
/// IoError when a file cannot be written, InputError when a certificate has
/// no data file to name (data made in memory). `written` (if given) gets
/// each file's path and bytes, for a caller that checks later that the
/// files still hold them.
CertificateFiles write_certificates(const CertifiedBounds& b, const std::string& certificate_path,
                                    WrittenFiles* written = nullptr);

/// Writes one certificate at `path` (placed_at); throws and records like write_certificates.
void write_certificate_at(const Certificate& c, const std::string& path, WrittenFiles* written = nullptr);

}  // namespace lpvid
