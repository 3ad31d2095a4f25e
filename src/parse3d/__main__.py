from parse3d.cli import main

main()
