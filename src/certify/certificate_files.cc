#include "certify/certificate_files.h"

#include <filesystem>

#include "core/input_error.h"

namespace lpvid {

std::string lower_certificate_path(const std::string& certificate_path) {
  namespace fs = std::filesystem;
  fs::path p(certificate_path);
  return (p.parent_path() / (p.stem().string() + ".lower.json")).string();
}

void write_certificate_at(const Certificate& c, const std::string& path) {
  bool named = c.records.empty() ? !c.data_sha256.empty() : true;
  for (const CertificateRecord& r : c.records) named = named && r.data.has_file();
  if (!named) throw InputError(path + ": the certificate names no data file (its experiment was not read from a file)");
  write_certificate(path, placed_at(c, path));
}

CertificateFiles write_certificates(const CertifiedBounds& b, const std::string& certificate_path) {
  CertificateFiles files;
  if (b.certificate) {
    write_certificate_at(*b.certificate, certificate_path);
    files.certificate = certificate_path;
  }
  if (b.lower.certificate) {
    files.lower = lower_certificate_path(certificate_path);
    write_certificate_at(*b.lower.certificate, files.lower);
  }
  return files;
}

}  // namespace lpvid
