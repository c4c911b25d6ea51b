"""The deterministic copy of examples/tutorial/04-periodic-simple-shear.py that tests/test_tutorials.py
compares with the reference: makeCloud with a seed, and the checker every 500 steps instead of every
second of wall-clock time (realPeriod), run to the end. Prints the copy:
    python3 tutorial04_copy.py > t.py && yade -n -x -j1 t.py   (then the saved O.tags['id'] + '.txt')"""
import os

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'examples', 'tutorial', '04-periodic-simple-shear.py')
CLOUD = 'sp.makeCloud((0, 0, 0), (2, 2, 2), rMean=.1, rRelFuzz=.6, periodic=True)'
CHECKER = "PyRunner(command='checkStress()', realPeriod=1, label='checker')"
RUN = "\nO.run()\nO.wait()\nprint('END', O.iter, O.cell.trsf[0, 2], len(plot.data['i']))\n"


def copy(seeded=True):
    with open(SOURCE) as f:
        text = f.read()
    assert CLOUD in text and CHECKER in text
    if seeded:
        text = text.replace(CLOUD, CLOUD[:-1] + ', seed=1)').replace(CHECKER, CHECKER.replace('realPeriod=1', 'iterPeriod=500'))
    return text + RUN


if __name__ == '__main__':
    print(copy())
