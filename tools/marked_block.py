"""marked_block.py - a generated block inside a hand-written Markdown page.

replace(path, begin, end, block): the text from the line `begin` to `end`
in the page at path becomes block (which starts with begin and ends with
end); without those markers block is appended. The rest stays as written."""
import os


def replace(path, begin, end, block):
    text = open(path).read() if os.path.exists(path) else ""
    if begin in text and end in text:
        text = text[:text.index(begin)] + block.rstrip("\n") + text[text.index(end) + len(end):]
    else:
        text = text.rstrip("\n") + "\n\n" + block
    with open(path, "w") as f:
        f.write(text)
