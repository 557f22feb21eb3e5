#!/usr/bin/python3
"""Draws the RAO table of `heavesim rao` (rao.h5) as rao.png beside it: per channel an
amplitude and a phase panel against the wave period, points from the time domain (H1
points with coherence below 0.9 faint), the line from the BEM data (docs/rao.md).
`heavesim rao` runs it after writing the table (unless --no-plot); by hand:

    /usr/bin/python3 scripts/plot_rao.py results/semisub_6dof_regular_wave_rao/rao.h5 [-o rao.png] [--channel heave ...]

Debian's /usr/bin/python3 with h5py and matplotlib; the table is read by the heavesim
package's pure-Python reader (python/heavesim/rao.py), which needs no build.
"""
import argparse
import os
import pathlib
import sys

# The reader is pure Python: take it from the source tree, so that the figure needs no build.
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "python"))
from heavesim import rao  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("table", help="rao.h5 written by heavesim rao")
    parser.add_argument("-o", "--output", help="figure (default rao.png beside the table)")
    parser.add_argument("--channel", action="append", help="channels to draw (default all)")
    args = parser.parse_args()
    table = rao.read(args.table)
    output = args.output or os.path.join(os.path.dirname(os.path.abspath(args.table)), "rao.png")
    unknown = [c for c in args.channel or [] if c not in table.channels]
    if unknown:
        print(f"plot_rao.py: no channel {unknown[0]!r} in {args.table} (it has {', '.join(table.channels)})",
              file=sys.stderr)
        return 2
    rao.figure(table, output, channels=args.channel)
    print("wrote", output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
