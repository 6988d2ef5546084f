// An engine's first contact with kumite: read a capture through the installed package.
#include <kumite/formats/bvh_reader.h>
#include <kumite/runtime/retrieval_worker.h>

#include <iostream>

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    const kumite::Result<kumite::BvhFile> file = kumite::bvh_read_file(argv[1]);
    if (!file) {
        std::cerr << file.error().message << "\n";
        return 1;
    }
    kumite::LatestValue<int> mailbox; // the runtime's headers and library are installed too
    mailbox.slot() = file->clip.skeleton.joint_count();
    mailbox.publish();
    if (!mailbox.take()) return 1;
    std::cout << mailbox.current() << " joints\n";
    return file->clip.skeleton.joint_count() == 2 ? 0 : 1;
}
