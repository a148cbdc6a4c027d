int main() { return 0; } // placeholder until the workbench lands
