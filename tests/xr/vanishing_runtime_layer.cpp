// An OpenXR API layer that makes the runtime vanish mid-session, for the test of `kumite play --xr` losing its
// runtime: every call passes through to the real runtime (Monado) until the session has waited
// KUMITE_VANISH_AFTER_FRAMES frames (default 40); from then on the frame calls and xrPollEvent answer
// XR_ERROR_INSTANCE_LOST, as a runtime that crashed or was closed does. Enabled through the loader's own mechanism
// (XR_API_LAYER_PATH naming the folder of its manifest, XR_ENABLE_API_LAYERS its name); nothing in kumite knows it.
// The loader's negotiation structs are declared as the OpenXR loader ABI defines them (openxr_loader_negotiation.h,
// which Debian 12's libopenxr-dev does not install).

#include <openxr/openxr.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <type_traits>

extern "C" {

enum XrLoaderInterfaceStructs {
    XR_LOADER_INTERFACE_STRUCT_UNINTIALIZED = 0,
    XR_LOADER_INTERFACE_STRUCT_LOADER_INFO = 1,
    XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST = 2,
    XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST = 3,
    XR_LOADER_INTERFACE_STRUCT_API_LAYER_CREATE_INFO = 4,
    XR_LOADER_INTERFACE_STRUCT_API_LAYER_NEXT_INFO = 5,
    XR_LOADER_INTERFACE_STRUCTS_MAX_ENUM = 0x7FFFFFFF
};
struct XrApiLayerCreateInfo;
typedef XrResult(XRAPI_PTR* PFN_xrCreateApiLayerInstance)(const XrInstanceCreateInfo*, const XrApiLayerCreateInfo*, XrInstance*);
struct XrApiLayerNextInfo {
    XrLoaderInterfaceStructs structType;
    uint32_t structVersion;
    size_t structSize;
    char layerName[XR_MAX_API_LAYER_NAME_SIZE];
    PFN_xrGetInstanceProcAddr nextGetInstanceProcAddr;
    PFN_xrCreateApiLayerInstance nextCreateApiLayerInstance;
    XrApiLayerNextInfo* next;
};
struct XrApiLayerCreateInfo {
    XrLoaderInterfaceStructs structType;
    uint32_t structVersion;
    size_t structSize;
    void* loaderInstance;
    char settings_file_location[512];
    XrApiLayerNextInfo* nextInfo;
};
struct XrNegotiateLoaderInfo {
    XrLoaderInterfaceStructs structType;
    uint32_t structVersion;
    size_t structSize;
    uint32_t minInterfaceVersion, maxInterfaceVersion;
    XrVersion minApiVersion, maxApiVersion;
};
struct XrNegotiateApiLayerRequest {
    XrLoaderInterfaceStructs structType;
    uint32_t structVersion;
    size_t structSize;
    uint32_t layerInterfaceVersion;
    XrVersion layerApiVersion;
    PFN_xrGetInstanceProcAddr getInstanceProcAddr;
    PFN_xrCreateApiLayerInstance createApiLayerInstance;
};

} // extern "C"

namespace {

PFN_xrGetInstanceProcAddr g_next_get_proc = nullptr;
PFN_xrWaitFrame g_next_wait = nullptr;
PFN_xrBeginFrame g_next_begin = nullptr;
PFN_xrEndFrame g_next_end = nullptr;
PFN_xrPollEvent g_next_poll = nullptr;
std::atomic<long> g_frames{0};

long vanish_after() {
    const char* text = std::getenv("KUMITE_VANISH_AFTER_FRAMES");
    return text ? std::atol(text) : 40;
}
bool vanished() { return g_frames.load() >= vanish_after(); }

XrResult XRAPI_CALL wait_frame(XrSession session, const XrFrameWaitInfo* info, XrFrameState* state) {
    if (vanished()) return XR_ERROR_INSTANCE_LOST;
    const XrResult result = g_next_wait(session, info, state);
    if (XR_SUCCEEDED(result)) ++g_frames;
    return result;
}
XrResult XRAPI_CALL begin_frame(XrSession session, const XrFrameBeginInfo* info) {
    return vanished() ? XR_ERROR_INSTANCE_LOST : g_next_begin(session, info);
}
XrResult XRAPI_CALL end_frame(XrSession session, const XrFrameEndInfo* info) {
    // The frame waited last still ends: the runtime goes between frames.
    return g_frames.load() > vanish_after() ? XR_ERROR_INSTANCE_LOST : g_next_end(session, info);
}
XrResult XRAPI_CALL poll_event(XrInstance instance, XrEventDataBuffer* event) {
    return vanished() ? XR_ERROR_INSTANCE_LOST : g_next_poll(instance, event);
}

XrResult XRAPI_CALL get_instance_proc_addr(XrInstance instance, const char* name, PFN_xrVoidFunction* function) {
    if (!g_next_get_proc) return XR_ERROR_HANDLE_INVALID; // asked before the instance exists
    const XrResult result = g_next_get_proc(instance, name, function);
    if (XR_FAILED(result)) return result;
    auto replace = [&](auto& next, auto ours) {
        next = reinterpret_cast<std::remove_reference_t<decltype(next)>>(*function);
        *function = reinterpret_cast<PFN_xrVoidFunction>(ours);
    };
    if (std::strcmp(name, "xrWaitFrame") == 0) replace(g_next_wait, &wait_frame);
    else if (std::strcmp(name, "xrBeginFrame") == 0) replace(g_next_begin, &begin_frame);
    else if (std::strcmp(name, "xrEndFrame") == 0) replace(g_next_end, &end_frame);
    else if (std::strcmp(name, "xrPollEvent") == 0) replace(g_next_poll, &poll_event);
    return result;
}

XrResult XRAPI_CALL create_api_layer_instance(const XrInstanceCreateInfo* info, const XrApiLayerCreateInfo* layer_info, XrInstance* instance) {
    if (!layer_info || !layer_info->nextInfo) return XR_ERROR_INITIALIZATION_FAILED;
    g_next_get_proc = layer_info->nextInfo->nextGetInstanceProcAddr;
    XrApiLayerCreateInfo next_info = *layer_info;
    next_info.nextInfo = layer_info->nextInfo->next;
    return layer_info->nextInfo->nextCreateApiLayerInstance(info, &next_info, instance);
}

} // namespace

extern "C" __attribute__((visibility("default"))) XrResult XRAPI_CALL xrNegotiateLoaderApiLayerInterface(const XrNegotiateLoaderInfo* loader_info,
                                                                                                         const char*, XrNegotiateApiLayerRequest* request) {
    if (!loader_info || !request || loader_info->structType != XR_LOADER_INTERFACE_STRUCT_LOADER_INFO ||
        request->structType != XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST || loader_info->minInterfaceVersion > 1 || loader_info->maxInterfaceVersion < 1) {
        return XR_ERROR_INITIALIZATION_FAILED;
    }
    request->layerInterfaceVersion = 1;
    request->layerApiVersion = XR_CURRENT_API_VERSION;
    request->getInstanceProcAddr = get_instance_proc_addr;
    request->createApiLayerInstance = create_api_layer_instance;
    return XR_SUCCESS;
}
