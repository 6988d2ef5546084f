// An engine's first contact with kumite: read a capture through the installed package.
#include <kumite/formats/bvh_reader.h>

#include <iostream>

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    const kumite::Result<kumite::BvhFile> file = kumite::bvh_read_file(argv[1]);
    if (!file) {
        std::cerr << file.error().message << "\n";
        return 1;
    }
    std::cout << file->clip.skeleton.joint_count() << " joints\n";
    return file->clip.skeleton.joint_count() == 2 ? 0 : 1;
}
