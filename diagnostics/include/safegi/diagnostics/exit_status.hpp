#pragma once
// The exit status of every SafeGI program (safeglslc, safegi-lsp's command
// line, safegi-render*, safegi-preview*), as docs/safeglslc.md and
// docs/cpu-renderer.md say: the command line's mistakes apart from the input's.

namespace safegi {

inline constexpr int kExitSuccess = 0;     // done (warnings allowed)
inline constexpr int kExitInputError = 1;  // the input has errors, or the job cannot be done (I/O, memory)
inline constexpr int kExitUsage = 2;       // the command line is wrong: unknown option, bad or missing value

}  // namespace safegi
