from lagrade.cli import run

run()
