from lagrade.cli import main

main()
