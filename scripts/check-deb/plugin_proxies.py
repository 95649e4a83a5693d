"""The plugin's proxies, looked up in the running ParaView's proxy definitions."""
from paraview import servermanager

FILTERS = ["MobiusRegistration", "SphericalConformalMap", "MobiusCenter", "SphericalScaleGrid",
           "SO3Register",
           "DenseCorrespondence", "RefineCorrespondence", "DetectSymmetry", "SphericalOrbifoldMap"]


def check_plugin_proxies():
    definitions = servermanager.ProxyManager().SMProxyManager.GetProxyDefinitionManager()
    missing = [name for name in FILTERS if not definitions.HasDefinition("filters", name)]
    assert not missing, f"filters not in the proxy list (plugin not loaded at start-up): {missing}"
    return f"all {len(FILTERS)} filters of the plugin in the proxy list"
