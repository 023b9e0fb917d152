"""``python -m actors <group> <verb>``: the command line."""

import sys

from actors.cli import main

sys.exit(main())
