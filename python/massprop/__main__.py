"""`python -m massprop ARGS…`: the `massprop` command, as on the command line."""

from __future__ import annotations

import os
import sys

from massprop._find import find_massprop_bin


def main() -> None:
    binary = find_massprop_bin()
    if sys.platform == "win32":
        # Windows has no exec that keeps the console's process: wait for it
        # and pass its status on.
        import subprocess

        try:
            status = subprocess.run([binary, *sys.argv[1:]]).returncode
        except KeyboardInterrupt:
            status = 130
        sys.exit(status)
    # Replace this process: signals, the terminal and the exit status are
    # the binary's own.
    os.execv(binary, [binary, *sys.argv[1:]])


if __name__ == "__main__":
    main()
