# Shared by tests/direct/generate.py and generate_patterns.py: the mean and
# standard error of repeated rows, and the expected.txt format that
# tests/direct/direct_matrix_test.cpp reads (described in generate.py).
import math


def mean_and_sem(rows, rays, repeat):
    """Per input ray: the mean of its `repeat` output rows, and the standard
    error of each mean."""
    groups = [rows[i * repeat:(i + 1) * repeat] for i in range(rays)]
    means = [[sum(g[k][j] for k in range(repeat)) / repeat for j in range(len(g[0]))]
             for g in groups]
    sems = [[math.sqrt(sum((g[k][j] - m[j]) ** 2 for k in range(repeat)) / (repeat - 1) / repeat)
             for j in range(len(m))] for g, m in zip(groups, means)]
    return means, sems


def write_expected(path, header, blocks):
    """blocks: dicts with group name files rays repeat options check status
    err rows notes sems."""
    with open(path, "w") as f:
        f.write(header)
        for b in blocks:
            f.write(f"case {b['group']} {b['name']}\nfiles {' '.join(b['files'])}\n"
                    f"rays {b['rays']} {b['repeat']}\noptions {b['options']}\n"
                    f"check {b['check']}\nstatus {b['status']}\n")
            for line in b["err"]:
                f.write(f"err {line}\n")
            for line in b["notes"]:
                f.write(f"note {line}\n")
            for row in b["rows"]:
                f.write("out " + " ".join("%.7g" % v for v in row) + "\n")
            for row in b["sems"]:
                f.write("sem " + " ".join("%.4g" % v for v in row) + "\n")
            f.write("end\n")
