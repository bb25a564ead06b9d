"""The reproduction pipeline (see README.md, "What is where").

Importing ``jsonschema`` costs ~2 s of CPU in this environment: the ``jupyter`` metapackage
installs ``jsonschema[format-nongpl]``, whose ``rfc3987-syntax`` compiles lark grammars at
import, only to check the ``iri`` and ``iri-reference`` formats. No schema of this project uses
a ``format`` keyword (tests/shared/test_bad_config.py checks it), so the package is hidden from
jsonschema before any module of the pipeline imports it: ~0.2 s instead, in each of the ~30
processes of a reproduction. The other format checkers' packages that only jsonschema imports
(``isoduration``, which imports ``arrow``, and five small ones) are hidden too: ~0.07 s of CPU
less per process.
"""

import sys

#: packages jsonschema imports only to check ``format`` keywords, which no schema here uses
HIDDEN_FORMAT_PACKAGES = (
    "rfc3987_syntax",
    "isoduration",
    "uri_template",
    "webcolors",
    "fqdn",
    "rfc3339_validator",
    "rfc3986_validator",
)
for _name in HIDDEN_FORMAT_PACKAGES:
    sys.modules.setdefault(_name, None)  # type: ignore[arg-type]
del _name
