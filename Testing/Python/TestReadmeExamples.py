"""Runs every ```python block of the README, in order and each in a fresh
namespace, from a folder holding CGAL's data/meshes (as the README says to
extract them). The blocks assert their own results.

Usage: pvpython TestReadmeExamples.py <README.md> <site-packages> <folder with data/meshes>
"""
import os
import re
import sys

readme, site_packages, data_folder = sys.argv[1:4]
sys.path.insert(0, site_packages)
blocks = re.findall(r"```python\n(.*?)```", open(readme, encoding="utf-8").read(), re.S)
assert len(blocks) >= 3, f"expected the README's Python examples, found {len(blocks)}"
os.chdir(data_folder)
for i, code in enumerate(blocks, 1):
    print(f"--- README Python example {i}", flush=True)
    exec(compile(code, f"README example {i}", "exec"), {"__name__": "__main__"})
print(f"all {len(blocks)} README Python examples ran")
