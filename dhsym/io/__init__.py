"""Input and output: the safe expression parser (`expr`), hostile-YAML reading (`yamlsafe`),
robot-file validation (`robotfile`), built-in robots (`library`) and atomic writes (`output`)."""
