// Token pasting for the self-registration macros (HWINTERP_SUBCOMMAND,
// HWINTERP_PAPER): one static object per line.
#pragma once

#define HWINTERP_CONCAT_INNER(a, b) a##b
#define HWINTERP_CONCAT(a, b) HWINTERP_CONCAT_INNER(a, b)
