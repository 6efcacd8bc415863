#pragma once
/// One colour per role, used by every figure (diagnose, compare, tradeoff):
/// the same role has the same colour in each of them, and a reader who
/// learned the colours in one figure reads them in the next. Colours from
/// Paul Tol's colour-blind-safe "bright" and "grey" sets. A residual is drawn
/// in the colour of the model it belongs to (before, after).

namespace lpvid::palette {

inline constexpr const char* kMeasured = "#000000";     ///< the measured signal
inline constexpr const char* kInput = "#aa3377";        ///< a measured input (purple)
inline constexpr const char* kModelBefore = "#ee7733";  ///< the model before (the declared or fitted one), orange
inline constexpr const char* kModelAfter = "#0077bb";   ///< the model after (diagnosed, re-fitted), blue
inline constexpr const char* kBound = "#cc3311";        ///< a certified bound or a confidence band's edge, red
inline constexpr const char* kBoundBand = "#ee99aa";    ///< the area of a certified bound (d_max band), light red
inline constexpr const char* kSecondaryBound = "#ccbb44";  ///< a second, looser band (95 % beside 99 %), yellow
inline constexpr const char* kWarmup = "#bbbbbb";       ///< warm-up rows (x0 fit, not scored), grey shading
inline constexpr const char* kSelection = "#dddddd";    ///< selection blocks (held-out folds), light grey shading
inline constexpr const char* kSelectionAlternate = "#cccccc";  ///< every second selection block (they abut)
inline constexpr const char* kReference = "#555555";    ///< a reference line: zero, the identity map

/// Further models of one figure (compare: model k), after the roles above.
inline constexpr const char* kOtherModels[] = {"#0077bb", "#ee7733", "#009988", "#cc3311", "#33bbee", "#aa3377"};

}  // namespace lpvid::palette
