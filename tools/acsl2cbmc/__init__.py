# SPDX-License-Identifier: Apache-2.0
"""acsl2cbmc: translate the kernel's ACSL contracts into C that CBMC checks.

Run as `python3 tools/acsl2cbmc [options]` (usage and semantics: __main__.py). Modules, in
the order of the pipeline: errors, ctype, cparse (C tokens and declarations), acsl
(ACSL tokens and parser), contracts (contracts and logic definitions), frontend
(preprocess and collect), translate (terms and predicates to C), generate (the output
files), __main__ (the command line).
"""
