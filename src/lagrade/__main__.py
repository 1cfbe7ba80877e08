from lagrade.launch import run

run()
