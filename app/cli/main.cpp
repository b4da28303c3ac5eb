#include <cstdio>
int main() { std::puts("granota-cli"); return 0; }
