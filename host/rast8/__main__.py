"""python -m rast8 == the rast8 command."""
import sys

from .cli import main

sys.exit(main())
