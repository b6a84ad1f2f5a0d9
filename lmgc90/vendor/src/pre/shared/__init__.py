__all__=['tact_behav','bulk_behav','model']
