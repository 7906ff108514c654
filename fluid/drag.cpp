// drag: to be written
