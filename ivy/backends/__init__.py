"""One package per framework. Each exports exactly the same public names, with the same file
names as ``ivy/core/``; ``tests/ivy/test_namespaces.py`` enforces both."""
