"""What the structure checks (test_include_floors.py, test_doc_citations.py) share: the verdict of a self-test
that planted faults in a scratch tree, and the command line (ROOT, or --self-test)."""
import sys


def self_test_verdict(planted, missed, false_reports, fault):
    """Prints each planted fault the check missed and each report it should not have made; 0 when neither."""
    for rel in missed:
        print(f"self-test: the {fault} in {rel} was not reported")
    for p in false_reports:
        print(f"self-test: reported what is allowed: {p}")
    print(f"self-test: {len(planted) - len(missed)} of {len(planted)} {fault}s caught, {len(false_reports)} false reports")
    return 1 if missed or false_reports else 0


def main(doc, check, self_test, label, noun):
    """check(root) -> problem lines, counted as "label: N noun" ("include floors: 0 offending includes")."""
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if len(sys.argv) != 2:
        print(doc)
        return 2
    problems = check(sys.argv[1])
    for p in problems:
        print(p)
    print(f"{label}: {len(problems)} {noun}")
    return 1 if problems else 0
