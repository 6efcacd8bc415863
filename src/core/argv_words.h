#pragma once
/// An argv (program name first, then the arguments, then a null pointer)
/// built from strings, for parsers that take (argc, argv) as main() does:
/// the command lines that run in-process parse their arguments exactly as
/// their programs parse the real argv.

#include <string>
#include <vector>

namespace lpvid {

class ArgvWords {
 public:
  ArgvWords(const std::string& program, const std::vector<std::string>& args) : words_{program} {
    words_.insert(words_.end(), args.begin(), args.end());
    for (std::string& w : words_) pointers_.push_back(w.data());
    pointers_.push_back(nullptr);
  }
  ArgvWords(const ArgvWords&) = delete;  // pointers_ point into words_
  ArgvWords& operator=(const ArgvWords&) = delete;

  int argc() const { return static_cast<int>(words_.size()); }
  char** argv() { return pointers_.data(); }

 private:
  std::vector<std::string> words_;
  std::vector<char*> pointers_;
};

}  // namespace lpvid
