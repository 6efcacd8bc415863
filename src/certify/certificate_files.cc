#include "certify/certificate_files.h"

#include <filesystem>

#include "core/file_io.h"
#include "core/input_error.h"

namespace lpvid {

std::string lower_certificate_path(const std::string& certificate_path) {
  namespace fs = std::filesystem;
  fs::path p(certificate_path);
  return (p.parent_path() / (p.stem().string() + ".lower.json")).string();
}

void write_certificate_at(const Certificate& c, const std::string& path, WrittenFiles* written) {
  bool named = !c.records.empty();
  for (const CertificateRecord& r : c.records) named = named && r.data.has_file();
  if (!named) throw InputError(path + ": the certificate names no data file (its experiment was not read from a file)");
  const std::string text = certificate_json(placed_at(c, path));
  write_text_file(path, text, "certificate");
  if (written) (*written)[path] = text;
}

CertificateFiles write_certificates(const CertifiedBounds& b, const std::string& certificate_path, WrittenFiles* written) {
  CertificateFiles files;
  if (b.certificate) {
    write_certificate_at(*b.certificate, certificate_path, written);
    files.certificate = certificate_path;
  }
  if (b.lower.certificate) {
    files.lower = lower_certificate_path(certificate_path);
    write_certificate_at(*b.lower.certificate, files.lower, written);
  }
  return files;
}

}  // namespace lpvid
