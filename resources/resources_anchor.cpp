// The resource data of trueturn_resources is linked through Qt's object library; this file
// gives the static library a translation unit of its own.
namespace tt::resources {
int anchor() {
    return 0;
}
}  // namespace tt::resources
