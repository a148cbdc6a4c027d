namespace forcelab { int lessonsPlaceholder = 0; }
