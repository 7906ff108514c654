// porosity: to be written
