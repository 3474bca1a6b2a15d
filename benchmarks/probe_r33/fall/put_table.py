"""Put (or replace) the results-table section (a file) just before '## Findings' in README.md.
usage: put_table.py TABLE_SECTION.md"""
import critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r33/src"), _cm_check.__file__  # r33 snapshot
import sys
p = __file__.rsplit("/", 1)[0] + "/README.md"
s = open(p).read(); t = open(sys.argv[1]).read().strip("\n") + "\n\n"
a = s.find("\n## Results"); f = s.find("## Findings")
s = (s[:a + 1] if a >= 0 else s[:f]) + t + s[f:]
open(p, "w").write(s)
