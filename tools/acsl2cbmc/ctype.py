# SPDX-License-Identifier: Apache-2.0
"""C types of the kernel's declarations."""


class CType:
    """kind: int | bool | void | ptr | array | struct | enum | fn.  `alias` is the typedef
    name used to spell the type in generated code."""

    def __init__(self, kind, **kw):
        self.kind = kind
        self.alias = kw.get("alias")
        self.spell = kw.get("spell")      # C spelling of a base type ("unsigned int")
        self.to = kw.get("to")            # ptr/array target
        self.dim = kw.get("dim")          # array dimension text
        self.name = kw.get("name")        # struct/enum typedef name
        self.fields = kw.get("fields")    # struct: list of (name, CType)
        self.ret = kw.get("ret")          # fn
        self.params = kw.get("params")    # fn
        self.const = kw.get("const", False)

    def copy(self, **changes):
        t = CType.__new__(CType)
        t.__dict__.update(self.__dict__)
        t.__dict__.update(changes)
        return t

    def with_alias(self, alias):
        return self.copy(alias=alias)

    def is_intlike(self):
        return self.kind in ("int", "enum")

    def is_scalar(self):
        return self.kind in ("int", "enum", "bool", "ptr")

    def is_fnptr(self):
        return self.kind == "ptr" and self.to is not None and self.to.kind == "fn"

    def c(self, name="", const_target=False):
        """C declaration of `name` with this type."""
        if self.kind == "ptr":
            if self.to.kind == "fn":
                if self.alias:
                    return f"{self.alias} {name}".strip()
                ps = ", ".join(p.c() for p in self.to.params) or "void"
                return f"{self.to.ret.c()} (*{name})({ps})"
            inner = self.to.c()
            if const_target and not inner.startswith("const "):
                inner = "const " + inner
            if self.alias and not const_target:
                return f"{self.alias} {name}".strip()
            return f"{inner} *{name}".strip()
        if self.kind == "array":
            return self.to.c(f"{name}[{self.dim}]")
        base = self.alias or self.spell or (self.name if self.kind in ("struct", "enum") else None)
        if base is None:
            base = {"bool": "_Bool", "void": "void", "int": "int"}[self.kind]
        if self.const and not base.startswith("const "):
            base = "const " + base
        return f"{base} {name}".strip()

    def __repr__(self):
        return f"CType({self.kind},{self.alias or self.spell or self.name})"


BASE_INT_WORDS = {"char", "short", "int", "long", "signed", "unsigned", "__int128"}
QUALIFIERS = {"const", "volatile", "restrict", "__restrict", "__restrict__", "static", "inline",
              "__inline", "__inline__", "extern", "__extension__", "register", "_Noreturn",
              "__const"}
