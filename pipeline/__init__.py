"""The reproduction pipeline (see README.md, "What is where").

Importing ``jsonschema`` costs ~2 s of CPU in this environment: the ``jupyter`` metapackage
installs ``jsonschema[format-nongpl]``, whose ``rfc3987-syntax`` compiles lark grammars at
import, only to check the ``iri`` and ``iri-reference`` formats. No schema of this project uses
a ``format`` keyword (tests/shared/test_bad_config.py checks it), so the package is hidden from
jsonschema before any module of the pipeline imports it: ~0.2 s instead, in each of the ~30
processes of a reproduction.
"""

import sys

sys.modules.setdefault("rfc3987_syntax", None)  # type: ignore[arg-type]
