// lpvid-verify: placeholder until the verifier lands (issue 2).
#include <cstdio>
int main() { std::fprintf(stderr, "lpvid-verify: not built yet\n"); return 2; }
