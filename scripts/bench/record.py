"""Keeps a benchmark's printed block in results/: newest first, under the file's title line."""
import os


def prepend_block(path, title, lines, root):
    """Writes lines (the block as printed) at the top of path, below its first paragraph (the title),
    creating the file with title if it does not exist; prints where it went."""
    old = open(path).read() if os.path.exists(path) else title + "\n\n"
    head, _, rest = old.partition("\n\n")
    with open(path, "w") as f:
        f.write(head + "\n\n" + "\n".join(lines) + "\n\n" + rest)
    print("recorded in %s" % os.path.relpath(path, root))
