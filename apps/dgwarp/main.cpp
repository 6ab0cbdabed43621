#include <iostream>
int main() { std::cout << "dgwarp\n"; return 0; }
