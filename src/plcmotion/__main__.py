"""``python -m plcmotion`` is the same as the ``plcmotion`` command."""
import sys

from .cli import main

sys.exit(main())
