# SPDX-License-Identifier: Apache-2.0
"""Errors of the translator."""


class TranslateError(Exception):
    pass


class CParseError(TranslateError):
    """A C declaration the tolerant top-level walk may skip (system headers)."""


def fail(where, msg):
    raise TranslateError(f"{where}: {msg}")
