"""`python -m sovarc.compiler.cli`: the same as the `sovarc` script."""

import sys

from sovarc.compiler.cli import main

sys.exit(main())
