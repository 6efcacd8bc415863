// Turns off the contraction of a·b + c into one fused multiply-add for the
// functions that follow in the including file: include it after every other
// #include (so that the headers' own functions keep the build's setting).
// Code whose rounding a proof or a bit-for-bit promise fixes (each product
// and each sum rounded separately) needs it; a run-time probe should check
// that it took effect where a proof depends on it.
// No include guard on purpose: the pragma must reach each including file.
#if defined(__clang__)
#pragma clang fp contract(off)
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif
