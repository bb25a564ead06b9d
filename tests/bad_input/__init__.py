"""The bad-input corpus (issue 14): every entry point's bad inputs declared as data, one module
per entry point, all run by tests/bad_input/harness.py through the real entry point."""
