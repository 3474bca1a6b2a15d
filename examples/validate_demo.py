"""Check the audit's verdicts against brute-force full rollouts for one demo.

    python examples/validate_demo.py [--samples N]
"""

import argparse

import critmoment as cm
from critmoment import demos
from critmoment.validation import validate


def main(samples: int):
    twin = cm.Twin(cm.load_scenario())
    traj = demos.scripted_transfer(seed=0, twin=twin)
    result = validate(traj, twin=twin, n_samples=samples, seed=0)
    print(result.summary_text())
    return result


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--samples", type=int, default=64)
    main(parser.parse_args().samples)
