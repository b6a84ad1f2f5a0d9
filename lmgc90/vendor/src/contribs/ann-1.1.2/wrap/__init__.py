
all = ["ann_eucl", "ann_manh"]

