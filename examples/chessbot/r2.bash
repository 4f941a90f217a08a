#!/bin/bash
# The seed's aliases, for the chess robot (source ./r2.bash, then r2home). Poses in `world`, the hand
# pointing down: the left arm's home is over the board's left half, the right arm's over its right half.
R2_CLI="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/r2_cli.py"
alias r2lhome="python3 $R2_CLI left 0.05 1.3 1.15 3.14159 0 -0.785"
alias r2rhome="python3 $R2_CLI right 0.45 1.3 1.15 3.14159 0 -0.785"
alias r2home="r2lhome;r2rhome"
