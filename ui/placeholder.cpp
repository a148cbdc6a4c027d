namespace forcelab { int uiPlaceholder = 0; }
