// gas_solver: to be written
